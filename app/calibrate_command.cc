#include "app/calibrate_command.h"

#include <chrono>
#include <iostream>
#include <map>

#include "app/base_flag.h"
#include "app/cli_values.h"
#include "app/shard_output.h"
#include "app/variation_fit_output.h"
#include "common/error.h"
#include "common/one_line.h"
#include "common/input_log.h"
#include "models/model_paths.h"
#include "models/robot_spec.h"
#include "report/atomic_file.h"
#include "report/output_set.h"
#include "report/provenance.h"
#include "validation/calibration_html.h"
#include "validation/calibration_report.h"
#include "validation/calibration_shard.h"
#include "validation/observed_kicks.h"
#include "validation/physics_calibration.h"
#include "validation/variation_fit.h"

namespace foresight {

namespace {

constexpr int kMaxTrials = 1000000;
constexpr int kMaxThreads = 1024;

// The kicks to calibrate: --kick, or every kick of `available` with --all.
std::vector<std::string> ChosenKicks(const CalibrateOptions& options,
                                     const std::vector<std::string>& available,
                                     const std::string& where) {
  return ChooseKicks(options.all ? "" : options.kick, available, "--kick", where);
}

// The physics calibration of the flags: played, or (`parts`) merged from its shards.
void CalibrateFromPhysics(const CalibrateOptions& options, const std::filesystem::path& models,
                          CalibrationRun& run, const std::vector<ShardPart>* parts) {
  PhysicsCalibrationSettings settings;
  settings.robot = options.robot;
  settings.kick = options.all ? "" : options.kick;
  settings.trials = ParseCount("--trials", options.trials, 8, kMaxTrials);
  settings.seed = run.provenance.seed;
  settings.threads = ParseCount("--threads", options.threads, 0, kMaxThreads);
  settings.situation_file = options.situation_file;
  settings.kicks_file = options.kicks_file;
  settings.physics_file = options.physics_file;
  settings.base = ParseBaseFlag(options.base);
  if (!options.variation_file.empty()) {
    settings.variation = LoadTrialVariation(options.variation_file, options.robot);
    run.provenance.SetInput("variation", options.variation_file);
  }
  settings.progress = [](const std::string& kick) {
    return CommandProgress("calibrate " + kick, "trials");
  };
  PhysicsCalibration physics;
  if (parts) {
    physics = PlanPhysicsCalibration(settings, models);
    MergeCalibrationShards(physics, settings.trials, *parts);
  } else {
    physics = RunPhysicsCalibration(settings, models);
  }
  run.source = "physics";
  run.provenance.SetInput("situation", DisplayPath(physics.situation_file, models));
  run.provenance.SetInput("physics", DisplayPath(physics.physics_file, models));
  run.provenance.SetInput("field", physics.field);
  run.provenance.SetInput("robot_base", std::string(RobotBaseName(physics.base)));
  run.carpet_deceleration_mps2 = physics.carpet_deceleration_mps2;
  run.trials_per_kick = settings.trials;
  for (PhysicsKickTrials& trials : physics.kicks) {
    CalibratedKick kick;
    kick.fit.kick = trials.kick;
    kick.observations = std::move(trials.observations);
    kick.draws = std::move(trials.draws);
    kick.missed = trials.missed;
    kick.fell = trials.fell;
    kick.blocked = trials.blocked;
    kick.clearance = trials.clearance;
    run.kicks.push_back(std::move(kick));
  }
}

void CalibrateFromCsv(const CalibrateOptions& options, CalibrationRun& run, const KickModel& base) {
  const ObservedKicks observed =
      ReadObservedKicks(options.from_csv, base.rolling_deceleration_mps2);
  CheckObservedKicks(observed, base, options.from_csv);
  run.source = options.from_csv;
  run.speeds_from_rest = observed.speeds_from_rest;
  for (const std::string& name : ChosenKicks(options, observed.kick_names, options.from_csv)) {
    if (!base.Find(name)) {
      throw InputError(options.from_csv + ": kick: '" + name + "' is not a kick of " +
                       run.provenance.Input("base_kicks"));
    }
    CalibratedKick kick;
    kick.observations = observed.by_kick.at(name);
    kick.fit.kick = name;
    run.kicks.push_back(std::move(kick));
  }
}

// The launch offset the base model gives `kick` (0 when it has no such kick).
double BaseLaunchOffset(const KickModel& base, const std::string& kick) {
  const std::optional<int> index = base.Find(kick);
  return index ? base.kicks[*index].launch_offset_m : 0.0;
}

void Fit(CalibrationRun& run) {
  std::vector<KickObservation> all;
  for (const CalibratedKick& kick : run.kicks) {
    all.insert(all.end(), kick.observations.begin(), kick.observations.end());
  }
  // The deceleration first (rows with a launch and a rest, or trajectories): a log's rows that
  // have only a rest position get their speeds from it, not from the committed model's.
  run.deceleration = FitPooledDeceleration(all, run.settings);
  const double a = run.deceleration ? run.deceleration->deceleration_mps2
                                    : run.base.rolling_deceleration_mps2;
  std::vector<KickCalibration> fits;
  for (CalibratedKick& kick : run.kicks) {
    RederiveSpeedsFromRest(kick.observations, a, BaseLaunchOffset(run.base, kick.fit.kick));
    kick.fit = CalibrateKick(kick.fit.kick, kick.observations, run.settings);
    fits.push_back(kick.fit);
  }
  // The launch offsets with the deceleration the model gets (physics trials have launch
  // points; a CSV log does not, and its kicks keep the base model's offsets).
  for (std::size_t i = 0; i < run.kicks.size(); ++i) {
    run.kicks[i].fit.launch_offset = FitLaunchOffset(run.kicks[i].observations, a);
    fits[i].launch_offset = run.kicks[i].fit.launch_offset;
  }
  run.fitted = ApplyCalibration(run.base, fits, run.deceleration);
}

// The outputs of a calibration, located and checked (before the work) and written together: the
// report folder first, so that a model inside it becomes one of its files. They may not replace
// the log, the variation, the situation or the physics file the run reads; --kicks may be --out
// (a model recalibrated on itself, docs/PHYSICS.md).
OutputSet CalibrationOutputs(const CalibrateOptions& options) {
  OutputSet outputs;
  outputs.AddInput("the input --from-csv", options.from_csv);
  outputs.AddInput("the input --variation", options.variation_file);
  outputs.AddInput("the input --situation", options.situation_file);
  outputs.AddInput("the input --physics", options.physics_file);
  outputs.AddFolder("--report", options.report_dir);
  outputs.AddFile("--out", options.out_file);
  return outputs;
}

// The kick model the calibration starts from (--kicks, or the robot's shipped one). --out may
// replace it although the run reads it: a model recalibrated on itself (docs/PHYSICS.md).
std::filesystem::path BaseKicksFile(const CalibrateOptions& options,
                                    const std::filesystem::path& models) {
  const std::filesystem::path file = options.kicks_file.empty()
                                         ? DataFile(models, DataFolder::kKicks, options.robot)
                                         : std::filesystem::path(options.kicks_file);
  InputLog::Allow(file);
  return file;
}

std::string ModelNotes(const CalibrationRun& run) {
  std::string kicks;
  for (const CalibratedKick& k : run.kicks) kicks += (kicks.empty() ? "" : ", ") + k.fit.kick;
  const RunProvenance& p = run.provenance;
  return "Calibrated by foresight calibrate " + p.version + " from " + run.source +
         (run.trials_per_kick > 0 ? " (" + std::to_string(run.trials_per_kick) + " trials per kick)"
                                  : "") +
         ", seed " + std::to_string(p.seed) + ", kicks: " + kicks + "; other values from " +
         p.Input("base_kicks") + ".";
}

}  // namespace

void AddCalibrateCommand(CLI::App& app, CalibrateOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "Fit a robot's kick noise model from physics trials or observed kicks");
  cmd->add_option("--robot", options.robot, "Robot (nao, aibo_ers7)")->required();
  auto* kick = cmd->add_option("--kick", options.kick, "The kick to calibrate");
  cmd->add_flag("--all", options.all, "Calibrate every kick of the robot")->excludes(kick);
  auto* trials =
      cmd->add_option("--trials", options.trials, "Physics trials per kick")->capture_default_str();
  cmd->add_option("--seed", options.seed, "Random seed")->capture_default_str();
  cmd->add_option("--threads", options.threads, "Worker threads (0: all cores)")
      ->capture_default_str();
  cmd->add_option("--out", options.out_file, "Kick-model file to write")->required();
  cmd->add_option("--report", options.report_dir, "Folder for the JSON, CSV and HTML report");
  cmd->add_option("--situation", options.situation_file,
                  "Where the robot kicks (default: MODELS/calibration/<robot>.json)");
  cmd->add_option("--kicks", options.kicks_file,
                  "Kick model to start from (default: MODELS/kicks/<robot>.json)");
  cmd->add_option("--physics", options.physics_file,
                  "Physics file (default: MODELS/physics/<field>.json)");
  AddBaseOption(*cmd, options.base);
  auto* variation = cmd->add_option(
      "--variation", options.variation_file,
      "Trial variation file (what --fit-variation writes) replacing robot.json's");
  cmd->add_option("--from-csv", options.from_csv,
                  "Fit observed kicks from this CSV instead of running physics")
      ->excludes(trials);
  cmd->add_flag("--fit-variation", options.fit_variation,
                "With --from-csv: fit the physical causes of the spread (placement, playback "
                "speed) so physics kicks spread as the logged ones; --out gets a variation file "
                "that calibrate --variation and simulate --variation read")
      ->excludes(variation);
  cmd->add_option("--fit-trials", options.fit_trials,
                  std::string("Physics trials per kick and run of --fit-variation (default: ") +
                      kDefaultFitTrials + ")");
  cmd->add_option("--confidence", options.confidence, "Interval level")->capture_default_str();
  cmd->add_option("--resamples", options.resamples, "Bootstrap resamples")->capture_default_str();
  cmd->add_option("--shard", options.shard,
                  "Play only the trials i with i mod N = I of every kick (I/N, from 0) and write "
                  "the folder --out; `foresight merge` fits and reports from all N");
}

namespace {

// --fit-variation: the observed spreads of the log, the physical causes fitted to them.
int RunVariationFit(const CalibrateOptions& options, const std::filesystem::path& models) {
  if (options.from_csv.empty()) throw InputError("--fit-variation: needs --from-csv LOG");
  if (!options.report_dir.empty()) throw InputError("--report: not with --fit-variation");
  OutputSet outputs = CalibrationOutputs(options);
  const KickModel base = LoadKickModel(BaseKicksFile(options, models));
  ObservedKicks observed = ReadObservedKicks(options.from_csv, base.rolling_deceleration_mps2);
  CheckObservedKicks(observed, base, options.from_csv);
  // Rest-only rows' speeds with the log's own deceleration, as calibrate fits it.
  std::vector<KickObservation> all;
  for (const auto& [name, rows] : observed.by_kick) all.insert(all.end(), rows.begin(), rows.end());
  const std::optional<DecelerationFit> deceleration =
      FitPooledDeceleration(all, CalibrationSettings{});
  const double a = deceleration ? deceleration->deceleration_mps2 : base.rolling_deceleration_mps2;
  std::map<std::string, LaunchSpread> spreads;
  for (const std::string& name : ChosenKicks(options, observed.kick_names, options.from_csv)) {
    RederiveSpeedsFromRest(observed.by_kick.at(name), a, BaseLaunchOffset(base, name));
    spreads[name] = SpreadOf(observed.by_kick.at(name));
  }
  VariationFitSettings settings;
  settings.robot = options.robot;
  settings.trials = ParseCount(
      "--fit-trials", options.fit_trials.empty() ? kDefaultFitTrials : options.fit_trials, 50,
      kMaxTrials);
  settings.seed = ParseSeed(options.seed);
  settings.threads = ParseCount("--threads", options.threads, 0, kMaxThreads);
  settings.base = ParseBaseFlag(options.base);
  settings.progress = [](const std::string& kick) {
    return CommandProgress("fit-variation " + kick, "trials");
  };
  const VariationFit fit = FitVariation(settings, spreads, models);
  const std::string json = VariationFitJson(options.robot, options.from_csv, fit).dump(2) + "\n";
  const std::string text = PrintableLines(VariationFitText(fit));
  outputs.Put("--out", json);
  outputs.Commit();
  std::cout << text << "wrote the fitted trial_variation to " << options.out_file
            << " (physics reads it with calibrate --variation " << options.out_file
            << " or simulate --variation " << options.out_file << ")\n"
            << std::flush;
  if (!std::cout) throw InputError("cannot write to standard output");
  return 0;
}

}  // namespace

CalibrationRun CalibrateInMemory(const CalibrateOptions& options,
                                 const std::filesystem::path& models,
                                 const std::vector<ShardPart>* parts) {
  const auto start = std::chrono::steady_clock::now();
  CalibrationRun run;
  run.provenance.version = FORESIGHT_VERSION;
  run.robot = options.robot;
  run.provenance.seed = ParseSeed(options.seed);
  run.settings.seed = run.provenance.seed;
  run.settings.confidence = ParseNumber("--confidence", options.confidence, 0.5, 0.999);
  run.settings.resamples = ParseCount("--resamples", options.resamples, 100, 100000);
  const std::filesystem::path base_file = BaseKicksFile(options, models);
  run.base = LoadKickModel(base_file);
  if (run.base.robot != options.robot) {
    throw InputError(base_file.string() + ": robot: the kick model is for '" + run.base.robot +
                     "', not --robot '" + options.robot + "'");
  }
  // The report's order; physics fills in the first two, a CSV leaves them empty.
  run.provenance.inputs = {{"situation", ""},
                           {"physics", ""},
                           {"field", ""},
                           {"base_kicks", DisplayPath(base_file, models)},
                           {"base_kicks_hash", ContentHash(base_file)},
                           {"out", options.out_file}};
  if (options.from_csv.empty()) {
    if (options.kick.empty() && !options.all) throw InputError("--kick or --all: say which kicks");
    CalibrateFromPhysics(options, models, run, parts);
  } else {
    if (!options.variation_file.empty()) {
      throw InputError("--variation: only for physics calibration, not with --from-csv");
    }
    CalibrateFromCsv(options, run, run.base);
  }
  if (options.from_csv.empty()) {
    Fit(run);
  } else {
    WithFile(options.from_csv, [&] { Fit(run); });  // a log too short for a fit names the log
  }
  run.provenance.run_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

namespace {

constexpr char kCalibrateCommand[] = "calibrate";

// The flags that decide a physics calibration's results, as a shard records them.
nlohmann::ordered_json CalibrateSettings(const CalibrateOptions& o) {
  return {{"--robot", o.robot},       {"--kick", o.kick},         {"--all", o.all},
          {"--trials", o.trials},     {"--seed", o.seed},         {"--situation", o.situation_file},
          {"--kicks", o.kicks_file},  {"--physics", o.physics_file}, {"--base", o.base},
          {"--variation", o.variation_file},
          {"--confidence", o.confidence}, {"--resamples", o.resamples}};
}

// --shard: this shard's trials of every kick into the folder --out.
int RunCalibrationShard(const CalibrateOptions& options, const Shard& shard,
                        const std::filesystem::path& models) {
  const auto start = std::chrono::steady_clock::now();
  if (!options.from_csv.empty() || options.fit_variation || !options.report_dir.empty())
    throw InputError("--shard: only for physics calibration, with --out DIR and no --report");
  if (options.kick.empty() && !options.all) throw InputError("--kick or --all: say which kicks");
  OutputSet outputs = ReportFolderOutput(options.out_file);  // before the work, not after
  PhysicsCalibrationSettings settings;
  settings.robot = options.robot;
  settings.kick = options.all ? "" : options.kick;
  const int trials = ParseCount("--trials", options.trials, 8, kMaxTrials);
  settings.trials = trials;
  settings.seed = ParseSeed(options.seed);
  settings.threads = ParseCount("--threads", options.threads, 0, kMaxThreads);
  settings.situation_file = options.situation_file;
  settings.kicks_file = options.kicks_file;
  settings.physics_file = options.physics_file;
  settings.base = ParseBaseFlag(options.base);
  if (!options.variation_file.empty()) {
    settings.variation = LoadTrialVariation(options.variation_file, options.robot);
  }
  settings.shard = shard;
  const PhysicsCalibration part = RunPhysicsCalibration(settings, models);
  const ShardHeader header{kCalibrateCommand, FORESIGHT_VERSION, shard, CalibrateSettings(options),
                           trials};
  WriteShardFolder(outputs, options.out_file, header, CalibrationShardResults(part, shard, trials),
                   start, "trials per kick");
  return 0;
}

}  // namespace

// Writes the model and the report into `outputs`: --out and --report of calibrate, or merge's
// one folder --out holding both (`model_in_report`).
int WriteCalibration(const CalibrateOptions& options, const CalibrationRun& run, OutputSet& outputs,
                     bool model_in_report);

int RunCalibrate(const CalibrateOptions& options, const std::string& models_dir) {
  const std::filesystem::path models =
      models_dir.empty() ? DefaultModelsDir() : std::filesystem::path(models_dir);
  // --robot bogus: the robots there, not a kick model that is missing.
  WithFile("--robot", [&] { RobotSpecFile(options.robot, models); });
  if (const std::optional<Shard> shard = ParseShardFlag(options.shard))
    return RunCalibrationShard(options, *shard, models);
  if (options.fit_variation) return RunVariationFit(options, models);
  if (!options.fit_trials.empty()) throw InputError("--fit-trials: only with --fit-variation");
  OutputSet outputs = CalibrationOutputs(options);  // before the work, not after
  return WriteCalibration(options, CalibrateInMemory(options, models), outputs, false);
}

int MergeCalibrationCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                            const std::string& out_dir, const std::filesystem::path& models) {
  const ShardPart& first = parts.front();
  CalibrateOptions options;
  options.robot = SettingString(first, "--robot");
  options.kick = SettingString(first, "--kick");
  options.all = SettingFlag(first, "--all");
  options.trials = SettingString(first, "--trials");
  options.seed = SettingString(first, "--seed");
  options.situation_file = SettingString(first, "--situation");
  options.kicks_file = SettingString(first, "--kicks");
  options.physics_file = SettingString(first, "--physics");
  options.base = SettingString(first, "--base");
  options.variation_file = SettingString(first, "--variation");
  options.confidence = SettingString(first, "--confidence");
  options.resamples = SettingString(first, "--resamples");
  // What `calibrate --report DIR --out DIR/ROBOT_calibrated.json` writes, as merge's one folder
  // --out (declared by RunMergeCommand).
  options.report_dir = out_dir;
  options.out_file = (std::filesystem::path(out_dir) / (options.robot + "_calibrated.json")).string();
  if (first.header.items != ParseCount("--trials", options.trials, 8, kMaxTrials)) {
    throw InputError(first.file.string() + ": items: " + std::to_string(first.header.items) +
                     " trials, but settings.--trials is " + options.trials);
  }
  CalibrationRun run = CalibrateInMemory(options, models, &parts);
  run.provenance.run_time_s = ShardsRunTime(parts);
  return WriteCalibration(options, run, outputs, true);
}

int WriteCalibration(const CalibrateOptions& options, const CalibrationRun& run, OutputSet& outputs,
                     bool model_in_report) {
  // Everything is made before anything is written, and the model is read back through the
  // kick-model reader first: a fit from damaged data (a merged shard's) is refused, not written.
  const std::string model = KickModelJson(run.fitted, ModelNotes(run));
  ParseKickModel(model, options.out_file + " (the calibrated model, not written)");
  ReportFiles files;
  if (!options.report_dir.empty()) {
    const std::filesystem::path dir(options.report_dir);
    files.push_back({dir / "calibration.json", CalibrationJson(run).dump(2) + "\n"});
    files.push_back({dir / "calibration_kicks.csv", CalibrationObservationsCsv(run)});
    files.push_back({dir / "calibration_summary.csv", CalibrationSummaryCsv(run)});
    files.push_back({dir / "calibration.html", CalibrationHtml(run)});
  }
  const std::string text = PrintableLines(CalibrationText(run));  // names from data files
  if (model_in_report) {
    files.push_back({options.out_file, model});
    outputs.Put("--out", ReportFolderFiles(files));
  } else {
    outputs.Put("--out", model);
    if (!options.report_dir.empty()) outputs.Put("--report", ReportFolderFiles(files));
  }
  outputs.Commit();  // the model and the report together, or neither
  std::cout << text << "wrote the calibrated kick model to " << options.out_file << "\n";
  if (!options.report_dir.empty()) {
    std::cout << "report: "
              << (std::filesystem::path(options.report_dir) / "calibration.html").string() << "\n";
  }
  std::cout << std::flush;
  if (!std::cout) throw InputError("cannot write to standard output");
  return 0;
}

}  // namespace foresight
