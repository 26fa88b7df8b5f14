#include "app/ablations_command.h"

#include <chrono>

#include "app/cli_values.h"
#include "app/experiment_output.h"
#include "app/shard_output.h"
#include "experiments/passing_ablations.h"
#include "experiments/passing_shard.h"
#include "models/model_paths.h"

namespace foresight {

namespace {

// The inputs of an ablations run: both teams' and the variants, each checked before the work.
struct AblationsInputs {
  PassingInputs in;
  std::vector<PassingVariant> variants;
};

AblationsInputs LoadAblationsInputs(const PassingOptions& o, const std::filesystem::path& models) {
  AblationsInputs a{LoadPassingInputs(o, "both", models), LoadPassingVariants(o.variants, models)};
  for (const PassingVariant& v : a.variants) v.Apply(a.in.setup);  // every variant valid
  return a;
}

void WriteAblationsReport(OutputSet& outputs, const PassingOptions& o, const AblationsInputs& a,
                          const std::vector<PassingResult>& results, double run_time_s,
                          const std::filesystem::path& models) {
  const std::uint64_t seed = ParseSeed(o.seed);
  AblationRun run = SummariseAblations(a.in.setup, a.variants, results);
  run.provenance = PassingProvenance(o, a.in, "cbr variants",
                                     DisplayPath(a.in.setup.cbr.file, models), seed, models);
  run.provenance.SetInput(
      "variants",
      DisplayPath(ResolveModelFile(o.variants, DataFolder::kExperiments, ".", models), models));
  run.provenance.run_time_s = run_time_s;
  const std::filesystem::path dir(o.out_dir);
  const ReportFiles files = {{dir / "ablations.json", AblationsJson(run).dump(2) + "\n"},
                             {dir / "ablations.csv", AblationsCsv(run)},
                             {dir / "ablations.svg", AblationsSvg(run)}};
  WriteReport(outputs, o.out_dir, files, AblationsText(run), "ablations.svg");
}

// The flags that decide an ablations run's results, as a shard records them.
nlohmann::ordered_json Settings(const PassingOptions& o) {
  nlohmann::ordered_json settings = PassingSettings(o);
  settings["--variants"] = o.variants;
  return settings;
}

}  // namespace

void AddAblationsCommand(CLI::App& experiment, PassingOptions& o) {
  CLI::App* cmd = experiment.add_subcommand(
      "ablations", "The CBR team's variants and the reactive team from the same trial keys");
  AddPassingRunOptions(*cmd, o);
  cmd->add_option("--variants", o.variants, "Variants file, or a name in MODELS/experiments/")
      ->capture_default_str();
}

int RunAblationsCommand(const PassingOptions& o, const std::filesystem::path& models) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t seed = ParseSeed(o.seed);
  const int threads = ParseCount("--threads", o.threads, 0, 1024);
  const std::optional<Shard> shard = ParseShardFlag(o.shard);
  const AblationsInputs a = LoadAblationsInputs(o, models);
  OutputSet outputs = ReportFolderOutput(o.out_dir);  // before the work, not after
  const std::vector<PassingResult> results =
      PlayAblations(a.in.setup, a.variants, *a.in.executor, seed, threads,
                    CommandProgress("ablations", "trials"), shard.value_or(Shard{}));
  if (shard) {
    const std::vector<std::string> teams = AblationTeams(a.variants);
    const ShardHeader header{kAblationsCommand, FORESIGHT_VERSION, *shard, Settings(o),
                             PassingItems(a.in.setup, static_cast<int>(teams.size()))};
    WriteShardFolder(outputs, o.out_dir, header,
                     PassingShardResults(a.in.setup, teams, results, *shard), start, "trials");
    return 0;
  }
  WriteAblationsReport(outputs, o, a, results, SecondsSince(start), models);
  return 0;
}

int MergeAblationsCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                          const std::string& out_dir, const std::filesystem::path& models) {
  PassingOptions o = PassingOptionsOf(parts.front(), out_dir);
  o.variants = SettingString(parts.front(), "--variants");
  const AblationsInputs a = LoadAblationsInputs(o, models);
  const std::vector<std::string> teams = AblationTeams(a.variants);
  RequireShardItems(parts.front(), PassingItems(a.in.setup, static_cast<int>(teams.size())),
                    "trials");
  WriteAblationsReport(outputs, o, a, MergePassingShards(a.in.setup, teams, parts),
                       ShardsRunTime(parts), models);
  return 0;
}

}  // namespace foresight
