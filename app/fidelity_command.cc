#include "app/fidelity_command.h"

#include <chrono>
#include <iostream>

#include "app/base_flag.h"
#include "app/cli_values.h"
#include "app/shard_output.h"
#include "common/error.h"
#include "common/one_line.h"
#include "models/model_paths.h"
#include "report/provenance.h"
#include "validation/fidelity_html.h"
#include "validation/fidelity_report.h"
#include "validation/fidelity_shard.h"
#include "validation/fidelity_views.h"

namespace foresight {

void AddFidelityCommand(CLI::App& app, FidelityOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "fidelity", "Compare the coarse model's rankings and decisions with physics");
  cmd->add_option("--situations", options.situations,
                  "Situation set: a file, or a name in MODELS/fidelity/ (default, quick)")
      ->capture_default_str();
  cmd->add_option("--trials", options.trials, "Physics trials per candidate")
      ->capture_default_str();
  cmd->add_option("--samples", options.samples, "Coarse samples N (0: the evaluation file's)")
      ->capture_default_str();
  cmd->add_option("--converged", options.converged, "Samples of the converged coarse model")
      ->capture_default_str();
  cmd->add_option("--seed", options.seed, "Random seed")->capture_default_str();
  cmd->add_option("--threads", options.threads, "Worker threads (0: all cores)")
      ->capture_default_str();
  cmd->add_option("--kicks", options.kicks_file, "Kick model replacing every situation's");
  cmd->add_option("--physics", options.physics_file,
                  "Physics file (default: MODELS/physics/<field>.json)");
  AddBaseOption(*cmd, options.base);
  cmd->add_option("--class", options.situation_class,
                  "Only the set's situations of this class (e.g. near_posts)");
  cmd->add_option("--coarse-rebounds", options.coarse_rebounds,
                  "on or off: the coarse roll rebounds off posts, nets and robots (default: the "
                  "evaluation files')");
  cmd->add_option("--out", options.out_dir, "Folder for the report")->required();
  AddShardOption(*cmd, options.shard);
}

namespace {

// The flags that decide a fidelity run's results, as a shard records them.
nlohmann::ordered_json FidelitySettingsOf(const FidelityOptions& o) {
  return {{"--situations", o.situations}, {"--trials", o.trials},
          {"--samples", o.samples},       {"--converged", o.converged},
          {"--seed", o.seed},             {"--kicks", o.kicks_file},
          {"--physics", o.physics_file},  {"--class", o.situation_class},
          {"--coarse-rebounds", o.coarse_rebounds}, {"--base", o.base}};
}

// The run's settings, its set and its provenance (run time aside).
struct FidelityPlan {
  FidelityRun run;
  FidelitySet set;
};

FidelityPlan PlanFidelity(const FidelityOptions& options, const std::filesystem::path& models) {
  FidelityPlan plan;
  FidelityRun& run = plan.run;
  run.provenance.version = FORESIGHT_VERSION;
  run.settings.physics_trials = ParseCount("--trials", options.trials, 2, 100000);
  run.settings.coarse_samples = ParseCount("--samples", options.samples, 0, 1000000);
  run.settings.converged_samples = ParseCount("--converged", options.converged, 1, 10000000);
  run.settings.seed = run.provenance.seed = ParseSeed(options.seed);
  run.settings.threads = ParseCount("--threads", options.threads, 0, 1024);
  run.settings.physics_file = options.physics_file;
  run.settings.base = ParseBaseFlag(options.base);
  run.settings.progress = CommandProgress("fidelity", "situations");
  SituationOverrides overrides;
  overrides.kicks_file = options.kicks_file;
  overrides.coarse_rebounds = ParseSwitch("--coarse-rebounds", options.coarse_rebounds);
  overrides.physics_file = options.physics_file;
  plan.set = LoadFidelitySet(options.situations, models, overrides, options.situation_class);
  // What the situations used: robot, field, kick model (with its content hash) and the physics
  // file each one's trials read (--physics, else MODELS/physics/<field>.json).
  std::vector<std::string> robots, fields, kick_models, kick_hashes, physics_files;
  std::vector<std::filesystem::path> physics_paths;
  for (const FidelityCase& c : plan.set.cases) {
    robots.push_back(c.situation.kicks.robot);
    fields.push_back(c.situation.field.name);
    kick_models.push_back(DisplayPath(c.situation.kicks_file, models));
    kick_hashes.push_back(ContentHash(c.situation.kicks_file));
    physics_paths.push_back(options.physics_file.empty()
                                ? DataFile(models, DataFolder::kPhysics, c.situation.field.name)
                                : std::filesystem::path(options.physics_file));
    physics_files.push_back(DisplayPath(physics_paths.back(), models));
  }
  run.provenance.inputs = {
      {"situations_set", plan.set.name},
      {"set_file", DisplayPath(plan.set.file, models)},
      {"robot", JoinDistinct(robots)},
      {"field", JoinDistinct(fields)},
      {"kick_model", JoinDistinct(kick_models)},
      {"kick_model_hash", JoinDistinct(kick_hashes)},
      {"physics_file", JoinDistinct(physics_files)},
      {"class", options.situation_class.empty() ? "all" : options.situation_class},
      {"coarse_rebounds",
       options.coarse_rebounds.empty() ? "as the evaluation files" : options.coarse_rebounds},
      {"robot_base", BaseUsed(run.settings.base, physics_paths)}};
  run.rotations_rad = plan.set.rotations_rad;
  return plan;
}

int WriteFidelityReport(OutputSet& outputs, const std::string& out_dir, const FidelityRun& run,
                        const std::filesystem::path& models) {
  const std::filesystem::path dir(out_dir);
  ReportFiles files = {{dir / "fidelity.json", FidelityJson(run).dump(2) + "\n"},
                       {dir / "fidelity_candidates.csv", FidelityCandidatesCsv(run)},
                       {dir / "fidelity_situations.csv", FidelitySituationsCsv(run)},
                       {dir / "fidelity.html", FidelityHtml(run)}};
  // The worst situations in 3D, linked from fidelity.html, from the trials recorded in the run.
  for (auto& [name, page] : FidelityViewPages(run.result, run.settings, models)) {
    files.push_back({dir / name, std::move(page)});
  }
  const std::string text = PrintableLines(FidelityText(run));  // names from data files
  outputs.Put("--out", ReportFolderFiles(files));
  outputs.Commit();
  std::cout << text << "report: " << (dir / "fidelity.html").string() << "\n" << std::flush;
  if (!std::cout) throw InputError("cannot write to standard output");
  return 0;
}

}  // namespace

int RunFidelityCommand(const FidelityOptions& options, const std::string& models_dir) {
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path models =
      models_dir.empty() ? DefaultModelsDir() : std::filesystem::path(models_dir);
  const std::optional<Shard> shard = ParseShardFlag(options.shard);
  FidelityPlan plan = PlanFidelity(options, models);
  OutputSet outputs = ReportFolderOutput(options.out_dir);  // before the work, not after
  FidelityRun& run = plan.run;
  if (shard) {
    run.settings.shard = *shard;
    const FidelityResult part = RunFidelity(plan.set, models, run.settings);
    const ShardHeader header{kFidelityCommand, FORESIGHT_VERSION, *shard,
                             FidelitySettingsOf(options), static_cast<int>(plan.set.cases.size())};
    WriteShardFolder(outputs, options.out_dir, header, FidelityShardResults(part), start,
                     "situations");
    return 0;
  }
  run.result = RunFidelity(plan.set, models, run.settings);
  run.provenance.run_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return WriteFidelityReport(outputs, options.out_dir, run, models);
}

FidelityRun RunFidelityInMemory(const FidelityOptions& options,
                                const std::filesystem::path& models) {
  const auto start = std::chrono::steady_clock::now();
  FidelityPlan plan = PlanFidelity(options, models);
  plan.run.result = RunFidelity(plan.set, models, plan.run.settings);
  plan.run.provenance.run_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return std::move(plan.run);
}

int MergeFidelityCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                         const std::string& out_dir, const std::filesystem::path& models) {
  const ShardPart& first = parts.front();
  FidelityOptions options;
  options.situations = SettingString(first, "--situations");
  options.trials = SettingString(first, "--trials");
  options.samples = SettingString(first, "--samples");
  options.converged = SettingString(first, "--converged");
  options.seed = SettingString(first, "--seed");
  options.kicks_file = SettingString(first, "--kicks");
  options.physics_file = SettingString(first, "--physics");
  options.situation_class = SettingString(first, "--class");
  options.coarse_rebounds = SettingString(first, "--coarse-rebounds");
  options.base = SettingString(first, "--base");
  options.out_dir = out_dir;
  FidelityPlan plan = PlanFidelity(options, models);
  RequireShardItems(first, static_cast<int>(plan.set.cases.size()), "situations");
  plan.run.result = MergeFidelityShards(plan.set, plan.run.settings, parts);
  plan.run.provenance.run_time_s = ShardsRunTime(parts);
  return WriteFidelityReport(outputs, out_dir, plan.run, models);
}

}  // namespace foresight
