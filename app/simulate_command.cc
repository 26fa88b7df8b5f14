#include "app/simulate_command.h"

#include <iostream>

#include "app/base_flag.h"
#include "app/cli_values.h"
#include "app/simulation_output.h"
#include "common/checks.h"
#include "common/error.h"
#include "common/one_line.h"
#include "models/model_paths.h"
#include "physics/physics_setup.h"
#include "report/output_set.h"

namespace foresight {

namespace {

constexpr int kMaxTrials = 1000000;
constexpr int kMaxThreads = 1024;
// --view-rate: a frame per second at least (a slower replay shows nothing of a kick); at most
// one per kick step of any physics file in models/physics (1 ms), beyond which frames repeat.
constexpr double kMinViewRateHz = 1.0;
constexpr double kMaxViewRateHz = 1000.0;
constexpr const char* kDefaultViewRateHz = "100";
// Every trial's scene stays in memory until the page is written, each costing about 2 MB plus
// 11 kB per Hz at its peak (the NAO's forward kick: 100 trials at 100 Hz took 343 MB, 20 at
// 1000 Hz 294 MB, without --view 33 MB; 100 at 1000 Hz 522 MB): a view holds at most 100
// trials and --trials times --view-rate at most 20000, about 450 MB for such kicks.
constexpr int kMaxViewTrials = 100;
constexpr double kMaxViewFramesPerS = 20000.0;

// --view-rate, checked against --view and the view's cap; 0 without --view (no scene recorded).
double ViewRateHz(const SimulateOptions& options, int trials) {
  if (options.view_file.empty() && !options.view_rate_hz.empty()) {
    throw InputError("--view-rate needs --view");
  }
  const std::string rate =
      options.view_rate_hz.empty() ? kDefaultViewRateHz : options.view_rate_hz;
  const double rate_hz = ParseNumber("--view-rate", rate, kMinViewRateHz, kMaxViewRateHz);
  if (options.view_file.empty()) return 0.0;
  const std::string kept = " (every trial's scene is kept until the page is written)";
  if (trials > kMaxViewTrials) {
    throw InputError("--view: replays at most " + std::to_string(kMaxViewTrials) + " trials" +
                     kept + ", got --trials " + std::to_string(trials));
  }
  if (trials * rate_hz > kMaxViewFramesPerS) {
    throw InputError("--view: " + std::to_string(trials) + " trials at " + FormatNumber(rate_hz) +
                     " Hz are " + FormatNumber(trials * rate_hz) +
                     " frames per simulated second, at most " + FormatNumber(kMaxViewFramesPerS) +
                     kept + ": fewer --trials or a lower --view-rate");
  }
  return rate_hz;
}

}  // namespace

void AddSimulateCommand(CLI::App& app, SimulateOptions& options) {
  CLI::App* cmd = app.add_subcommand("simulate", "Physics trials of one kick from a situation");
  cmd->add_option("--situation", options.situation_file, "Situation file (JSON)")->required();
  cmd->add_option("--kick", options.kick, "Name of the kick (as in the kick model)")->required();
  cmd->add_option("--kicks", options.kicks_file, "Kick model file replacing the situation's");
  cmd->add_option("--physics", options.physics_file,
                  "Physics file (default: MODELS/physics/<field>.json)");
  AddBaseOption(*cmd, options.base);
  cmd->add_option("--variation", options.variation_file,
                  "Trial variation file (calibrate --fit-variation) replacing robot.json's");
  cmd->add_option("--trials", options.trials, "Number of trials")->capture_default_str();
  cmd->add_option("--seed", options.seed, "Random seed")->capture_default_str();
  cmd->add_option("--threads", options.threads, "Worker threads (0: all cores)")
      ->capture_default_str();
  cmd->add_option("--rotation", options.rotation_deg,
                  "Turn around the ball before the kick, degrees (left positive)")
      ->capture_default_str();
  cmd->add_flag("--json", options.json, "Print every trial and the summary as JSON");
  cmd->add_option("--svg", options.svg_file, "Draw the rest positions on the field");
  cmd->add_option("--trace", options.trace_file, "Write the balls' trajectories as CSV");
  cmd->add_option("--view", options.view_file,
                  "Write a 3D viewer page (HTML) replaying every trial (docs/VIEWER.md)");
  cmd->add_option("--view-rate", options.view_rate_hz,
                  std::string("Frames per simulated second recorded for --view (default ") +
                      kDefaultViewRateHz + ")");
}

SimulationPlan PlanSimulation(const SimulateOptions& options, const std::filesystem::path& models) {
  SimulationPlan plan;
  KickTrialsRequest& request = plan.request;
  request.trials = ParseCount("--trials", options.trials, 1, kMaxTrials);
  request.seed = ParseSeed(options.seed);
  request.threads = ParseCount("--threads", options.threads, 0, kMaxThreads);
  request.rotation_rad =
      ParseNumber("--rotation", options.rotation_deg, -360.0, 360.0) * kDegToRad;
  const std::optional<RobotBase> base = ParseBaseFlag(options.base);
  SituationOverrides overrides;
  overrides.kicks_file = options.kicks_file;
  Situation situation = LoadSituation(options.situation_file, models, overrides);
  const std::optional<int> kick = situation.kicks.Find(options.kick);
  if (!kick) {
    throw InputError("--kick: no kick '" + options.kick + "' in " + situation.kicks_file.string() +
                     " (one of: " + situation.kicks.Names() + ")");
  }
  request.kick_index = *kick;
  plan.setup = LoadPhysicsSetup(std::move(situation), models, options.physics_file, base);
  if (!plan.setup->robot.FindMotion(options.kick)) {
    throw InputError("--kick: robot '" + plan.setup->robot.spec.name +
                     "' has no motion for kick '" + options.kick + "'");
  }
  if (!options.variation_file.empty()) {
    // The scene reads the robot's variation at every trial, so this is all it takes.
    plan.setup->robot.spec.variation =
        LoadTrialVariation(options.variation_file, plan.setup->robot.spec.name);
  }
  request.state = plan.setup->state;  // physics plays the world as it is: the mean state
  request.record_trace = !options.trace_file.empty();
  request.progress = CommandProgress("simulate", "trials");
  request.scene_rate_hz = ViewRateHz(options, request.trials);
  return plan;
}

int RunSimulate(const SimulateOptions& options, const std::string& models_dir) {
  const std::filesystem::path models =
      models_dir.empty() ? DefaultModelsDir() : std::filesystem::path(models_dir);
  OutputSet outputs;  // located and checked before the work, written together after it
  outputs.AddInput("the input --situation", options.situation_file);
  outputs.AddInput("the input --kicks", options.kicks_file);
  outputs.AddInput("the input --physics", options.physics_file);
  outputs.AddInput("the input --variation", options.variation_file);
  outputs.AddFile("--svg", options.svg_file);
  outputs.AddFile("--trace", options.trace_file);
  outputs.AddFile("--view", options.view_file);
  SimulationPlan plan = PlanSimulation(options, models);
  const auto& setup = plan.setup;
  KickTrialsRequest& request = plan.request;
  SimulationRun run;
  run.situation_file = options.situation_file;
  run.situation = &setup->situation;
  run.robot = &setup->robot;
  run.physics_file = setup->physics_file;
  run.variation_file = options.variation_file;
  run.base = setup->params.robot.base;
  run.models_dir = models;
  run.kick = options.kick;
  run.rotation_rad = request.rotation_rad;
  run.seed = request.seed;
  run.state = request.state;
  run.results = RunKickTrials(*setup->simulator, request);
  run.summary = Summarize(run.results);

  // Everything is made before anything is written, so a failure leaves no file behind.
  const std::string printed =
      options.json ? SimulationJson(run).dump(2, ' ', false,
                                              nlohmann::ordered_json::error_handler_t::replace) +
                         "\n"
                   : PrintableLines(SimulationText(run));  // names from data files
  if (outputs.Has("--svg")) outputs.Put("--svg", SimulationSvg(run));
  if (outputs.Has("--trace")) outputs.Put("--trace", SimulationTraceCsv(run));
  if (outputs.Has("--view")) outputs.Put("--view", SimulationViewHtml(run));
  outputs.Commit();
  std::cout << printed << std::flush;
  if (!std::cout) throw InputError("cannot write to standard output");
  return 0;
}

}  // namespace foresight
