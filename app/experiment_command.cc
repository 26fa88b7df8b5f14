#include "app/experiment_command.h"

#include <chrono>
#include <iostream>

#include "app/cli_values.h"
#include "app/passing_physics.h"
#include "app/report_text.h"
#include "app/shard_output.h"
#include "common/error.h"
#include "experiments/passing_ablations.h"
#include "experiments/passing_comparison.h"
#include "experiments/passing_example.h"
#include "experiments/passing_figures.h"
#include "experiments/passing_replay.h"
#include "experiments/passing_report.h"
#include "experiments/stability_report.h"
#include "experiments/stability_shard.h"
#include "experiments/strategies_shard.h"
#include "experiments/strategies_report.h"
#include "models/model_paths.h"
#include "physics/physics_setup.h"
#include "report/atomic_file.h"

namespace foresight {

namespace {

std::filesystem::path ModelsFolder(const std::string& models_dir) {
  return models_dir.empty() ? DefaultModelsDir() : std::filesystem::path(models_dir);
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// An experiment's version, seed and inputs: its params file, its scene's name and kick model.
RunProvenance ExperimentProvenance(const std::filesystem::path& params_file, const Situation& scene,
                                   std::uint64_t seed, const std::filesystem::path& models) {
  RunProvenance provenance;
  provenance.version = FORESIGHT_VERSION;
  provenance.seed = seed;
  provenance.inputs = {{"file", DisplayPath(params_file, models)},
                       {"situation", scene.name},
                       {"kicks", DisplayPath(scene.kicks_file, models)}};
  return provenance;
}

// Every output is computed before the first is written; each file is replaced atomically.
void WriteReport(const std::string& out_dir, const ReportFiles& files, const std::string& text,
                 const std::string& main_file) {
  WriteReportFiles(out_dir, "--out", files);
  std::cout << text << "figures and data: " << (std::filesystem::path(out_dir) / main_file).string()
            << " and the other files in " << out_dir << "\n"
            << std::flush;
  if (!std::cout) throw InputError("cannot write to standard output");
}

void AddStability(CLI::App& experiment, StabilityOptions& o) {
  CLI::App* cmd = experiment.add_subcommand(
      "stability", "How stable the decision is against the number of samples (paper, Fig. 4)");
  cmd->add_option("--params", o.params,
                  "Experiment file, or a name in MODELS/experiments/ (default: stability)");
  cmd->add_flag("--quick", o.quick, "The small grid of MODELS/experiments/stability_quick.json");
  cmd->add_option("--kicks", o.kicks_file, "Kick model replacing the scene's");
  cmd->add_option("--strategy", o.strategy,
                  "Decision strategy (default: the params file's): " + StrategyNames());
  cmd->add_option("--repeats", o.repeats, "Decisions per pose and sample count");
  cmd->add_option("--samples", o.samples, "Sample counts, e.g. 1-25,30-110/10");
  cmd->add_option("--seed", o.seed, "Random seed")->capture_default_str();
  cmd->add_option("--threads", o.threads, "Worker threads (0: all cores)")->capture_default_str();
  cmd->add_option("--out", o.out_dir, "Folder for the results")->required();
  AddShardOption(*cmd, o.shard);
}

void AddStrategies(CLI::App& experiment, StrategiesOptions& o) {
  CLI::App* cmd = experiment.add_subcommand(
      "strategies", "The four strategies from random starts until goal or out (Figs. 3, 5)");
  cmd->add_option("--params", o.params, "Experiment file, or a name in MODELS/experiments/")
      ->capture_default_str();
  cmd->add_option("--kicks", o.kicks_file, "Kick model replacing the scene's");
  cmd->add_option("--starts", o.starts, "Random start positions (default: the params file's)");
  cmd->add_flag("--physics", o.physics, "Execute every kick in the Bullet scene");
  cmd->add_option("--coarse-rebounds", o.coarse_rebounds,
                  "on or off: the coarse roll rebounds off posts, nets and robots (default: the "
                  "evaluation file's)");
  cmd->add_option("--physics-file", o.physics_file,
                  "Physics file (default: MODELS/physics/<field>.json)");
  cmd->add_option("--seed", o.seed, "Random seed")->capture_default_str();
  cmd->add_option("--threads", o.threads, "Worker threads (0: all cores)")->capture_default_str();
  cmd->add_option("--out", o.out_dir, "Folder for the results")->required();
  AddShardOption(*cmd, o.shard);
}

constexpr char kStabilityCommand[] = "experiment stability";

// The flags that decide a stability run's results, as a shard records them.
nlohmann::ordered_json StabilitySettings(const StabilityOptions& o) {
  return {{"--params", o.params},   {"--quick", o.quick},     {"--kicks", o.kicks_file},
          {"--strategy", o.strategy}, {"--repeats", o.repeats}, {"--samples", o.samples},
          {"--seed", o.seed}};
}

StabilityOptions StabilityOptionsOf(const ShardPart& part, const std::string& out_dir) {
  StabilityOptions o;
  o.params = SettingString(part, "--params");
  o.quick = SettingFlag(part, "--quick");
  o.kicks_file = SettingString(part, "--kicks");
  o.strategy = SettingString(part, "--strategy");
  o.repeats = SettingString(part, "--repeats");
  o.samples = SettingString(part, "--samples");
  o.seed = SettingString(part, "--seed");
  o.out_dir = out_dir;
  return o;
}

// The params of the flags, checked, and the report folder checked before the work.
StabilityParams LoadStabilityRun(const StabilityOptions& o, const std::filesystem::path& models) {
  if (o.quick && !o.params.empty()) throw InputError("--quick and --params exclude each other");
  const std::string name =
      o.params.empty() ? (o.quick ? "stability_quick" : "stability") : o.params;
  SituationOverrides overrides;
  overrides.kicks_file = o.kicks_file;
  StabilityParams params = LoadStabilityParams(name, models, overrides);
  if (!o.strategy.empty()) {
    const std::optional<Strategy> s = ParseStrategy(o.strategy);
    if (!s) {
      throw InputError("--strategy: unknown strategy '" + o.strategy +
                       "' (one of: " + StrategyNames() + ")");
    }
    params.strategy = *s;
  }
  if (!o.repeats.empty()) params.repeats = ParseCount("--repeats", o.repeats, 2, 100000);
  if (!o.samples.empty()) {
    params.sample_counts = ParseSampleCounts("--samples", o.samples);
    if (!std::ranges::binary_search(params.sample_counts, params.map_samples)) {
      params.map_samples = params.sample_counts.back();  // the map shows the largest N then
    }
  }
  WithFile("--strategy/--repeats/--samples with " + DisplayPath(params.file, models),
           [&] { params.Validate(); });
  CheckReportDir(o.out_dir, "--out");  // before hours of work, not after
  return params;
}

void WriteStabilityReport(const std::string& out_dir, const StabilityRun& run) {
  const std::filesystem::path dir(out_dir);
  const ReportFiles files = {{dir / "stability.json", StabilityJson(run).dump(2) + "\n"},
                             {dir / "stability.csv", StabilityCountsCsv(run)},
                             {dir / "stability_positions.csv", StabilityPositionsCsv(run)},
                             {dir / "stability.svg", StabilityPlotSvg(run)},
                             {dir / "stability_map.svg", StabilityMapSvg(run)}};
  WriteReport(out_dir, files, StabilityText(run), "stability.svg");
}

int RunStability(const StabilityOptions& o, const std::filesystem::path& models) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t seed = ParseSeed(o.seed);
  const int threads = ParseCount("--threads", o.threads, 0, 1024);
  const std::optional<Shard> shard = ParseShardFlag(o.shard);
  const StabilityParams params = LoadStabilityRun(o, models);
  const auto progress = TerminalProgress("stability:", "poses");
  if (shard) {
    const StabilityResult part = RunStability(params, seed, threads, progress, *shard);
    const ShardHeader header{kStabilityCommand, FORESIGHT_VERSION,  *shard,
                             StabilitySettings(o), StabilityItems(params)};
    WriteShardFolder(o.out_dir, header, StabilityShardResults(part, *shard), start, "poses");
    return 0;
  }
  StabilityRun run;
  run.provenance = ExperimentProvenance(params.file, params.situation, seed, models);
  run.params = &params;
  run.result = RunStability(params, seed, threads, progress);
  run.provenance.run_time_s = SecondsSince(start);
  WriteStabilityReport(o.out_dir, run);
  return 0;
}

int MergeStability(const std::vector<ShardPart>& parts, const std::string& out_dir,
                   const std::filesystem::path& models) {
  const StabilityOptions o = StabilityOptionsOf(parts.front(), out_dir);
  const std::uint64_t seed = ParseSeed(o.seed);
  const StabilityParams params = LoadStabilityRun(o, models);
  if (parts.front().header.items != StabilityItems(params)) {
    throw InputError(parts.front().file.string() + ": items: " +
                     std::to_string(parts.front().header.items) + " poses, but the run has " +
                     std::to_string(StabilityItems(params)) + " here (other data files?)");
  }
  StabilityRun run;
  run.provenance = ExperimentProvenance(params.file, params.situation, seed, models);
  run.params = &params;
  run.result = MergeStabilityShards(params, parts);
  run.provenance.run_time_s = ShardsRunTime(parts);
  WriteStabilityReport(out_dir, run);
  return 0;
}

constexpr char kStrategiesCommand[] = "experiment strategies";

// The flags that decide a strategies run's results, as a shard records them.
nlohmann::ordered_json StrategiesSettings(const StrategiesOptions& o) {
  return {{"--params", o.params},
          {"--kicks", o.kicks_file},
          {"--starts", o.starts},
          {"--physics", o.physics},
          {"--physics-file", o.physics_file},
          {"--coarse-rebounds", o.coarse_rebounds},
          {"--seed", o.seed}};
}

StrategiesOptions StrategiesOptionsOf(const ShardPart& part, const std::string& out_dir) {
  StrategiesOptions o;
  o.params = SettingString(part, "--params");
  o.kicks_file = SettingString(part, "--kicks");
  o.starts = SettingString(part, "--starts");
  o.physics = SettingFlag(part, "--physics");
  o.physics_file = SettingString(part, "--physics-file");
  o.coarse_rebounds = SettingString(part, "--coarse-rebounds");
  o.seed = SettingString(part, "--seed");
  o.out_dir = out_dir;
  return o;
}

// What a strategies run needs before its work: the params, the physics (with --physics; loaded
// also by a merge, which checks the inputs the same way) and the provenance.
struct StrategiesPlan {
  StrategiesParams params;
  std::unique_ptr<PhysicsSetup> physics;
  StrategiesRun run;
};

std::unique_ptr<StrategiesPlan> PlanStrategies(const StrategiesOptions& o,
                                               const std::filesystem::path& models) {
  auto plan = std::make_unique<StrategiesPlan>();
  const std::uint64_t seed = ParseSeed(o.seed);
  if (!o.physics && !o.physics_file.empty()) throw InputError("--physics-file needs --physics");
  StrategiesParams& params = plan->params;
  SituationOverrides overrides;
  overrides.kicks_file = o.kicks_file;
  overrides.coarse_rebounds = ParseSwitch("--coarse-rebounds", o.coarse_rebounds);
  overrides.physics_file = o.physics_file;
  params = LoadStrategiesParams(o.params, models, overrides);
  if (!o.starts.empty()) {
    params.starts = ParseCount("--starts", o.starts, 1, 10000000);
    params.example_start = std::min(params.example_start, params.starts - 1);
  }
  StrategiesRun& run = plan->run;
  run.provenance = ExperimentProvenance(params.file, params.situation, seed, models);
  run.provenance.SetInput("coarse_rebounds",
                          params.situation.evaluation.rebounds.enabled ? "on" : "off");
  run.params = &params;
  if (o.physics) {
    plan->physics = LoadPhysicsSetup(params.situation, models, o.physics_file);
    RequireAllKickMotions(*plan->physics, run.provenance.Input("kicks"));
    CheckReportDir(o.out_dir, "--out");  // before the work, not after
    run.provenance.SetInput("executor", "physics");
    run.provenance.SetInput("physics", DisplayPath(plan->physics->physics_file, models));
  } else {
    CheckReportDir(o.out_dir, "--out");
    run.provenance.SetInput("executor", "coarse");
  }
  return plan;
}

void WriteStrategiesReport(const std::string& out_dir, StrategiesRun& run) {
  run.summaries = SummariseStrategies(run.result);
  const std::filesystem::path dir(out_dir);
  const ReportFiles files = {{dir / "strategies.json", StrategiesJson(run).dump(2) + "\n"},
                             {dir / "strategies_runs.csv", StrategiesRunsCsv(run)},
                             {dir / "strategies_turns.svg", StrategiesTurnsSvg(run)},
                             {dir / "strategies_kicks.svg", StrategiesKicksSvg(run)},
                             {dir / "strategies_paths.svg", StrategiesPathsSvg(run)}};
  WriteReport(out_dir, files, StrategiesText(run), "strategies_turns.svg");
}

int RunStrategiesExperiment(const StrategiesOptions& o, const std::filesystem::path& models) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t seed = ParseSeed(o.seed);
  const int threads = ParseCount("--threads", o.threads, 0, 1024);
  const std::optional<Shard> shard = ParseShardFlag(o.shard);
  const std::unique_ptr<StrategiesPlan> plan = PlanStrategies(o, models);
  const OutcomeSimulator* executor = plan->physics ? &*plan->physics->simulator : nullptr;
  const auto progress = TerminalProgress("strategies:", "runs");
  if (shard) {
    const StrategiesResult part =
        RunStrategies(plan->params, executor, seed, threads, progress, *shard);
    const ShardHeader header{kStrategiesCommand, FORESIGHT_VERSION, *shard,
                             StrategiesSettings(o), plan->params.starts};
    WriteShardFolder(o.out_dir, header, StrategiesShardResults(plan->params, part, *shard), start,
                     "starts");
    return 0;
  }
  StrategiesRun& run = plan->run;
  run.result = RunStrategies(plan->params, executor, seed, threads, progress);
  run.provenance.run_time_s = SecondsSince(start);
  WriteStrategiesReport(o.out_dir, run);
  return 0;
}

int MergeStrategies(const std::vector<ShardPart>& parts, const std::string& out_dir,
                    const std::filesystem::path& models) {
  const StrategiesOptions o = StrategiesOptionsOf(parts.front(), out_dir);
  const std::unique_ptr<StrategiesPlan> plan = PlanStrategies(o, models);
  if (parts.front().header.items != plan->params.starts) {
    throw InputError(parts.front().file.string() + ": items: " +
                     std::to_string(parts.front().header.items) + " starts, but the run has " +
                     std::to_string(plan->params.starts) + " here (other data files?)");
  }
  StrategiesRun& run = plan->run;
  run.result = MergeStrategiesShards(plan->params, ParseSeed(o.seed), parts);
  run.provenance.run_time_s = ShardsRunTime(parts);
  WriteStrategiesReport(out_dir, run);
  return 0;
}

// The options passing and ablations share: which trials, how kicks are executed, where to.
void AddPassingRunOptions(CLI::App& cmd, PassingOptions& o) {
  cmd.add_option("--scenarios", o.scenarios, "Scenarios, e.g. 1-4 or 3,4 (default: all)");
  cmd.add_option("--trials", o.trials, "Trials per scenario (default: the configuration's)");
  cmd.add_flag("--mirror", o.mirror, "Attack the goal at -x instead (the mirrored game)");
  cmd.add_flag("--physics", o.physics, "Execute every kick in the Bullet scene");
  cmd.add_option("--physics-file", o.physics_file,
                  "Physics file (default: MODELS/physics/<field>.json)");
  cmd.add_option("--kicks", o.kicks_file, "AIBO kick model replacing the simulation file's");
  cmd.add_option("--params", o.params, "Experiment file, or a name in MODELS/experiments/")
      ->capture_default_str();
  cmd.add_option("--seed", o.seed, "Random seed")->capture_default_str();
  cmd.add_option("--threads", o.threads, "Worker threads (0: all cores)")->capture_default_str();
  cmd.add_option("--out", o.out_dir, "Folder for the results")->required();
}

void AddPassing(CLI::App& experiment, PassingOptions& o) {
  CLI::App* cmd = experiment.add_subcommand(
      "passing", "2-vs-2 attacks against DG or 2D opponents (Ros et al. 2009, sec. 5.2)");
  cmd->add_option("--config", o.config, "Opponents: dg, 2d or a configuration file")->required();
  cmd->add_option("--team", o.team, "Attacking team: " + PassingTeamNames())
      ->capture_default_str();
  AddPassingRunOptions(*cmd, o);
}

// One team's report files, named PREFIX.json, PREFIX_trials.csv, ...
void AddPassingFiles(const std::filesystem::path& dir, const std::string& prefix,
                     const PassingRun& run, ReportFiles& files) {
  files.push_back({dir / (prefix + ".json"), PassingJson(run).dump(2) + "\n"});
  files.push_back({dir / (prefix + "_trials.csv"), PassingTrialsCsv(run)});
  files.push_back({dir / (prefix + "_events.csv"), PassingEventsCsv(run)});
  files.push_back({dir / (prefix + "_outcomes.svg"), PassingOutcomesSvg(run)});
  files.push_back({dir / (prefix + "_possession.svg"), PassingPossessionSvg(run)});
  files.push_back({dir / (prefix + "_time.svg"), PassingTimeSvg(run)});
  for (std::size_t i = 0; i < run.result.scenarios.size(); ++i) {
    const std::string& name = run.result.scenarios[i].name;
    files.push_back({dir / (prefix + "_example_" + name + ".svg"), PassingExampleSvg(run, i)});
    files.push_back({dir / (prefix + "_replay_" + name + ".html"), PassingReplayHtml(run, i)});
  }
}

// The inputs of a passing run, loaded and checked, and the executor of its kicks.
struct PassingInputs {
  PassingSetup setup;
  std::unique_ptr<KickExecutor> executor;
  std::string physics_file;  // empty without --physics
};

PassingInputs LoadPassingInputs(const PassingOptions& o, const std::string& team,
                                const std::filesystem::path& models) {
  PassingRequest request;
  request.params = o.params;
  request.config = o.config;
  request.team = team;
  if (!o.scenarios.empty()) request.scenarios = ParseSampleCounts("--scenarios", o.scenarios);
  if (!o.trials.empty()) request.trials = ParseCount("--trials", o.trials, 1, 10000000);
  request.mirrored = o.mirror;
  request.kicks_file = o.kicks_file;
  if (!o.physics && !o.physics_file.empty()) throw InputError("--physics-file needs --physics");
  PassingInputs in{LoadPassingSetup(request, models), nullptr, ""};
  if (o.physics) {
    auto physics = std::make_unique<PhysicsKickExecutor>(in.setup.field, in.setup.kicks, models,
                                                         o.physics_file);
    in.physics_file = DisplayPath(physics->physics_file(), models);
    in.executor = std::move(physics);
  } else {
    in.executor = std::make_unique<CoarseKickExecutor>(in.setup.field,
                                                       in.setup.kicks.rolling_deceleration_mps2);
  }
  return in;
}

RunProvenance PassingProvenance(const PassingOptions& o, const PassingInputs& in,
                                const std::string& team, const std::string& team_file,
                                std::uint64_t seed, const std::filesystem::path& models) {
  const PassingSetup& setup = in.setup;
  RunProvenance p;
  p.version = FORESIGHT_VERSION;
  p.seed = seed;
  p.inputs = {{"file", DisplayPath(setup.params.file, models)},
              {"simulation", DisplayPath(setup.sim.file, models)},
              {"field", DisplayPath(setup.field_file, models)},
              {"kicks", DisplayPath(setup.kicks_file, models)},
              {"config", DisplayPath(setup.config.file, models)},
              {"team", team},
              {"team_file", team_file},
              {"executor", o.physics ? "physics" : "coarse"},
              {"mirrored", setup.mirrored ? "yes" : "no"}};
  if (o.physics) p.SetInput("physics", in.physics_file);
  return p;
}

int RunPassingExperiment(const PassingOptions& o, const std::filesystem::path& models) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t seed = ParseSeed(o.seed);
  const int threads = ParseCount("--threads", o.threads, 0, 1024);
  const PassingInputs in = LoadPassingInputs(o, o.team, models);
  const PassingSetup& setup = in.setup;
  CheckReportDir(o.out_dir, "--out");

  const std::filesystem::path dir(o.out_dir);
  const bool both = setup.teams.size() > 1;
  ReportFiles files;
  std::string text;
  std::vector<PassingRun> runs;
  for (const std::string& team : setup.teams) {
    PassingRun run;
    run.provenance = PassingProvenance(
        o, in, team,
        DisplayPath(team == "cbr" ? setup.cbr.file : setup.reactive.file, models), seed, models);
    run.setup = &setup;
    run.team = team;
    run.result = RunPassing(setup, team, *in.executor, seed, threads,
                            TerminalProgress("passing " + team + ":", "trials"));
    run.summaries = SummarisePassing(run.result, setup.params.confidence);
    run.provenance.run_time_s = SecondsSince(start);
    AddPassingFiles(dir, both ? "passing_" + team : "passing", run, files);
    text += PassingText(run);
    runs.push_back(std::move(run));
  }
  if (both) {
    std::vector<std::string> opponents;
    for (const OpponentSpec& spec : setup.config.opponents) opponents.push_back(spec.name);
    const PassingComparison comparison =
        ComparePassing(setup.teams[0], runs[0].result, setup.teams[1], runs[1].result, opponents,
                       setup.params.confidence);
    files.push_back({dir / "passing_teams.svg", PassingTeamsSvg(runs[0], runs[1])});
    files.push_back({dir / "passing_comparison.json",
                     PassingComparisonJson(comparison).dump(2) + "\n"});
    text += PassingComparisonText(comparison);
  }
  WriteReport(o.out_dir, files, text,
              both ? "passing_" + setup.teams[0] + "_outcomes.svg" : "passing_outcomes.svg");
  return 0;
}

int RunAblationsExperiment(const PassingOptions& o, const std::filesystem::path& models) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t seed = ParseSeed(o.seed);
  const int threads = ParseCount("--threads", o.threads, 0, 1024);
  const PassingInputs in = LoadPassingInputs(o, "both", models);
  std::vector<PassingVariant> variants = LoadPassingVariants(o.variants, models);
  for (const PassingVariant& v : variants) v.Apply(in.setup);  // every variant valid, before work
  CheckReportDir(o.out_dir, "--out");
  AblationRun run = RunAblations(in.setup, std::move(variants), *in.executor, seed, threads,
                                 TerminalProgress("ablations:", "trials"));
  run.provenance = PassingProvenance(o, in, "cbr variants",
                                     DisplayPath(in.setup.cbr.file, models), seed, models);
  run.provenance.SetInput(
      "variants",
      DisplayPath(ResolveModelFile(o.variants, DataFolder::kExperiments, ".", models), models));
  run.provenance.run_time_s = SecondsSince(start);
  const std::filesystem::path dir(o.out_dir);
  const ReportFiles files = {{dir / "ablations.json", AblationsJson(run).dump(2) + "\n"},
                             {dir / "ablations.csv", AblationsCsv(run)},
                             {dir / "ablations.svg", AblationsSvg(run)}};
  WriteReport(o.out_dir, files, AblationsText(run), "ablations.svg");
  return 0;
}

void AddAblations(CLI::App& experiment, PassingOptions& o) {
  CLI::App* cmd = experiment.add_subcommand(
      "ablations", "The CBR team's variants and the reactive team from the same trial keys");
  cmd->add_option("--config", o.config, "Opponents: dg, 2d or a configuration file")->required();
  cmd->add_option("--variants", o.variants,
                  "Variants file, or a name in MODELS/experiments/")->capture_default_str();
  AddPassingRunOptions(*cmd, o);
}

}  // namespace

void AddExperimentCommand(CLI::App& app, ExperimentOptions& options) {
  CLI::App* experiment =
      app.add_subcommand("experiment", "The papers' experiments: stability, strategies, passing, ablations");
  experiment->require_subcommand(1);
  AddStability(*experiment, options.stability);
  AddStrategies(*experiment, options.strategies);
  AddPassing(*experiment, options.passing);
  AddAblations(*experiment, options.ablations);
}

int RunExperimentCommand(const CLI::App& app, const ExperimentOptions& options,
                         const std::string& models_dir) {
  const CLI::App* experiment = app.get_subcommand("experiment");
  const std::filesystem::path models = ModelsFolder(models_dir);
  if (experiment->got_subcommand("stability")) return RunStability(options.stability, models);
  if (experiment->got_subcommand("passing")) return RunPassingExperiment(options.passing, models);
  if (experiment->got_subcommand("ablations")) {
    return RunAblationsExperiment(options.ablations, models);
  }
  return RunStrategiesExperiment(options.strategies, models);
}

bool IsExperimentShardCommand(const std::string& command) {
  return command == kStabilityCommand || command == kStrategiesCommand;
}

int MergeExperimentShards(const std::vector<ShardPart>& parts, const std::string& out_dir,
                          const std::filesystem::path& models) {
  if (parts.front().header.command == kStrategiesCommand)
    return MergeStrategies(parts, out_dir, models);
  return MergeStability(parts, out_dir, models);
}

}  // namespace foresight
