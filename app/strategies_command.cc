#include "app/strategies_command.h"

#include <chrono>
#include <memory>

#include "app/base_flag.h"
#include "app/cli_values.h"
#include "app/experiment_output.h"
#include "app/shard_output.h"
#include "common/error.h"
#include "experiments/strategies_report.h"
#include "experiments/strategies_shard.h"
#include "models/model_paths.h"
#include "physics/physics_setup.h"

namespace foresight {

namespace {

// The flags that decide a strategies run's results, as a shard records them.
nlohmann::ordered_json StrategiesSettings(const StrategiesOptions& o) {
  return {{"--params", o.params},
          {"--kicks", o.kicks_file},
          {"--starts", o.starts},
          {"--physics", o.physics},
          {"--physics-file", o.physics_file},
          {"--coarse-rebounds", o.coarse_rebounds},
          {"--base", o.base},
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
  o.base = SettingString(part, "--base");
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
  if (!o.physics && !o.base.empty()) throw InputError("--base needs --physics");
  const std::optional<RobotBase> base = ParseBaseFlag(o.base);
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
    plan->physics = LoadPhysicsSetup(params.situation, models, o.physics_file, base);
    RequireAllKickMotions(*plan->physics, run.provenance.Input("kicks"));
    run.provenance.SetInput("executor", "physics");
    run.provenance.SetInput("physics", DisplayPath(plan->physics->physics_file, models));
    run.provenance.SetInput("robot_base",
                            std::string(RobotBaseName(plan->physics->params.robot.base)));
  } else {
    run.provenance.SetInput("executor", "coarse");
  }
  return plan;
}

void WriteStrategiesReport(OutputSet& outputs, const std::string& out_dir, StrategiesRun& run) {
  run.summaries = SummariseStrategies(run.result);
  const std::filesystem::path dir(out_dir);
  const ReportFiles files = {{dir / "strategies.json", StrategiesJson(run).dump(2) + "\n"},
                             {dir / "strategies_runs.csv", StrategiesRunsCsv(run)},
                             {dir / "strategies_turns.svg", StrategiesTurnsSvg(run)},
                             {dir / "strategies_kicks.svg", StrategiesKicksSvg(run)},
                             {dir / "strategies_paths.svg", StrategiesPathsSvg(run)}};
  WriteReport(outputs, out_dir, files, StrategiesText(run), "strategies_turns.svg");
}

}  // namespace

void AddStrategiesCommand(CLI::App& experiment, StrategiesOptions& o) {
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
  AddBaseOption(*cmd, o.base);
  cmd->add_option("--seed", o.seed, "Random seed")->capture_default_str();
  cmd->add_option("--threads", o.threads, "Worker threads (0: all cores)")->capture_default_str();
  cmd->add_option("--out", o.out_dir, "Folder for the results")->required();
  AddShardOption(*cmd, o.shard);
}

int RunStrategiesCommand(const StrategiesOptions& o, const std::filesystem::path& models) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t seed = ParseSeed(o.seed);
  const int threads = ParseCount("--threads", o.threads, 0, 1024);
  const std::optional<Shard> shard = ParseShardFlag(o.shard);
  const std::unique_ptr<StrategiesPlan> plan = PlanStrategies(o, models);
  OutputSet outputs = ReportFolderOutput(o.out_dir);  // before the work, not after
  const OutcomeSimulator* executor = plan->physics ? &*plan->physics->simulator : nullptr;
  const auto progress = CommandProgress("strategies", "runs");
  if (shard) {
    const StrategiesResult part =
        RunStrategies(plan->params, executor, seed, threads, progress, *shard);
    const ShardHeader header{kStrategiesCommand, FORESIGHT_VERSION, *shard, StrategiesSettings(o),
                             plan->params.starts};
    WriteShardFolder(outputs, o.out_dir, header, StrategiesShardResults(plan->params, part, *shard),
                     start, "starts");
    return 0;
  }
  StrategiesRun& run = plan->run;
  run.result = RunStrategies(plan->params, executor, seed, threads, progress);
  run.provenance.run_time_s = SecondsSince(start);
  WriteStrategiesReport(outputs, o.out_dir, run);
  return 0;
}

int MergeStrategiesCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                           const std::string& out_dir, const std::filesystem::path& models) {
  const StrategiesOptions o = StrategiesOptionsOf(parts.front(), out_dir);
  const std::unique_ptr<StrategiesPlan> plan = PlanStrategies(o, models);
  RequireShardItems(parts.front(), plan->params.starts, "starts");
  StrategiesRun& run = plan->run;
  run.result = MergeStrategiesShards(plan->params, ParseSeed(o.seed), parts);
  run.provenance.run_time_s = ShardsRunTime(parts);
  WriteStrategiesReport(outputs, out_dir, run);
  return 0;
}

}  // namespace foresight
