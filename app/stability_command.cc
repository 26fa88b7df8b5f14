#include "app/stability_command.h"

#include "app/cli_values.h"
#include "app/experiment_output.h"
#include "app/shard_output.h"
#include "common/error.h"
#include "experiments/stability_report.h"
#include "experiments/stability_shard.h"
#include "models/model_paths.h"

namespace foresight {

namespace {

// The flags that decide a stability run's results, as a shard records them.
nlohmann::ordered_json StabilitySettings(const StabilityOptions& o) {
  return {{"--params", o.params},     {"--quick", o.quick},     {"--kicks", o.kicks_file},
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

// The params of the flags, checked.
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
  return params;
}

void WriteStabilityReport(OutputSet& outputs, const std::string& out_dir, const StabilityRun& run) {
  const std::filesystem::path dir(out_dir);
  const ReportFiles files = {{dir / "stability.json", StabilityJson(run).dump(2) + "\n"},
                             {dir / "stability.csv", StabilityCountsCsv(run)},
                             {dir / "stability_positions.csv", StabilityPositionsCsv(run)},
                             {dir / "stability.svg", StabilityPlotSvg(run)},
                             {dir / "stability_map.svg", StabilityMapSvg(run)}};
  WriteReport(outputs, out_dir, files, StabilityText(run), "stability.svg");
}

}  // namespace

void AddStabilityCommand(CLI::App& experiment, StabilityOptions& o) {
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

int RunStabilityCommand(const StabilityOptions& o, const std::filesystem::path& models) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t seed = ParseSeed(o.seed);
  const int threads = ParseCount("--threads", o.threads, 0, 1024);
  const std::optional<Shard> shard = ParseShardFlag(o.shard);
  const StabilityParams params = LoadStabilityRun(o, models);
  OutputSet outputs = ReportFolderOutput(o.out_dir);  // before hours of work, not after
  const auto progress = CommandProgress("stability", "poses");
  if (shard) {
    const StabilityResult part = RunStability(params, seed, threads, progress, *shard);
    const ShardHeader header{kStabilityCommand, FORESIGHT_VERSION, *shard, StabilitySettings(o),
                             StabilityItems(params)};
    WriteShardFolder(outputs, o.out_dir, header, StabilityShardResults(part, *shard), start,
                     "poses");
    return 0;
  }
  StabilityRun run;
  run.provenance = ExperimentProvenance(params.file, params.situation, seed, models);
  run.params = &params;
  run.result = RunStability(params, seed, threads, progress);
  run.provenance.run_time_s = SecondsSince(start);
  WriteStabilityReport(outputs, o.out_dir, run);
  return 0;
}

int MergeStabilityCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                          const std::string& out_dir, const std::filesystem::path& models) {
  const StabilityOptions o = StabilityOptionsOf(parts.front(), out_dir);
  const std::uint64_t seed = ParseSeed(o.seed);
  const StabilityParams params = LoadStabilityRun(o, models);
  RequireShardItems(parts.front(), StabilityItems(params), "poses");
  StabilityRun run;
  run.provenance = ExperimentProvenance(params.file, params.situation, seed, models);
  run.params = &params;
  run.result = MergeStabilityShards(params, parts);
  run.provenance.run_time_s = ShardsRunTime(parts);
  WriteStabilityReport(outputs, out_dir, run);
  return 0;
}

}  // namespace foresight
