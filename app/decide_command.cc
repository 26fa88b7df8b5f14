#include "app/decide_command.h"

#include <iostream>

#include "app/cli_values.h"
#include "app/decision_json.h"
#include "app/decision_svg.h"
#include "app/decision_text.h"
#include "common/checks.h"
#include "common/error.h"
#include "common/one_line.h"
#include "models/model_paths.h"
#include "report/output_set.h"

namespace foresight {

void AddDecideCommand(CLI::App& app, DecideOptions& options) {
  CLI::App* cmd =
      app.add_subcommand("decide", "Choose a kick for a situation with the coarse model");
  cmd->add_option("--situation", options.situation_file, "Situation file (JSON)")->required();
  cmd->add_option("--kicks", options.kicks_file, "Kick model file replacing the situation's");
  cmd->add_option("--strategy", options.strategy, "One of: " + StrategyNames())
      ->capture_default_str();
  cmd->add_option("--samples", options.samples,
                  "Samples per hypothesis (default: the evaluation file's N)");
  cmd->add_option("--seed", options.seed, "Random seed")->capture_default_str();
  cmd->add_flag("--json", options.json, "Print the decision as JSON instead of text");
  cmd->add_option("--svg", options.svg_file, "Draw the field and every sample's rest position");
}

namespace {

// Loads the situation, decides and hands the decided run to `use` (the planner lives only as
// long as the call).
template <typename Use>
auto WithDecision(const DecideOptions& options, const std::filesystem::path& models, Use&& use) {
  const std::optional<Strategy> strategy = ParseStrategy(options.strategy);
  if (!strategy) {
    throw InputError("--strategy: unknown strategy '" + options.strategy +
                     "' (one of: " + StrategyNames() + ")");
  }
  const bool samples_given = !options.samples.empty();
  const int samples_flag =
      samples_given ? ParseCount("--samples", options.samples, 1, kMaxSamples) : 0;
  const std::uint64_t seed = ParseSeed(options.seed);
  SituationOverrides overrides;
  overrides.kicks_file = options.kicks_file;
  const Situation situation = LoadSituation(options.situation_file, models, overrides);
  const int samples = samples_given ? samples_flag : situation.evaluation.samples;

  const CoarsePlanner planner(situation);
  const DecisionRun run{options.situation_file,
                        &planner,
                        planner.Decide(*strategy, samples, seed),
                        samples,
                        seed,
                        models};
  return use(run);
}

}  // namespace

nlohmann::ordered_json DecideJson(const DecideOptions& options,
                                  const std::filesystem::path& models) {
  return WithDecision(options, models, [](const DecisionRun& run) { return DecisionJson(run); });
}

int RunDecide(const DecideOptions& options, const std::string& models_dir) {
  const std::filesystem::path models =
      models_dir.empty() ? DefaultModelsDir() : std::filesystem::path(models_dir);
  OutputSet outputs;  // located and checked before the work; no output replaces an input
  outputs.AddInput("the input --situation", options.situation_file);
  outputs.AddInput("the input --kicks", options.kicks_file);
  outputs.AddFile("--svg", options.svg_file);
  return WithDecision(options, models, [&](const DecisionRun& run) {
    // Everything is made before anything is written, so a failure leaves no file behind.
    const std::string printed =
        options.json ? DecisionJson(run).dump(2, ' ', false,
                                              nlohmann::ordered_json::error_handler_t::replace) +
                           "\n"
                     : PrintableLines(DecisionText(run));  // names from data files
    if (outputs.Has("--svg")) outputs.Put("--svg", DecisionSvg(run));
    outputs.Commit();
    std::cout << printed << std::flush;
    if (!std::cout) throw InputError("cannot write to standard output");
    return 0;
  });
}

}  // namespace foresight
