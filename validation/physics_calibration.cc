#include "validation/physics_calibration.h"

#include "common/error.h"
#include "models/model_paths.h"
#include "models/situation.h"
#include "physics/physics_runs.h"
#include "physics/physics_setup.h"

namespace foresight {

namespace {

std::unique_ptr<PhysicsSetup> LoadCalibrationSetup(const PhysicsCalibrationSettings& settings,
                                                   const std::filesystem::path& situation_file,
                                                   const std::filesystem::path& models) {
  SituationOverrides overrides;
  overrides.kicks_file = settings.kicks_file;
  auto setup = LoadPhysicsSetup(LoadSituation(situation_file, models, overrides), models,
                                settings.physics_file, settings.base);
  if (setup->situation.kicks.robot != settings.robot) {
    throw InputError(situation_file.string() + ": kicks: the kick model is for robot '" +
                     setup->situation.kicks.robot + "', not '" + settings.robot + "'");
  }
  return setup;
}

// The kicks of the model the robot has a motion for, in the model's order.
std::vector<std::string> KicksWithMotion(const PhysicsSetup& setup) {
  std::vector<std::string> names;
  for (const KickSpec& k : setup.situation.kicks.kicks) {
    if (setup.robot.FindMotion(k.name)) names.push_back(k.name);
  }
  return names;
}

PhysicsKickTrials PlayKick(const PhysicsSetup& setup, const PhysicsCalibrationSettings& settings,
                           const std::string& name) {
  PhysicsKickTrials kick;
  kick.kick = name;
  kick.kick_index = *setup.situation.kicks.Find(name);
  KickTrialsRequest request;
  request.state = setup.state;
  request.kick_index = kick.kick_index;
  request.trials = settings.trials;
  request.seed = CalibrationSeed(settings.seed, kick.kick_index);
  request.threads = settings.threads;
  request.record_trace = true;  // the rolling samples of the deceleration fit
  request.shard = settings.shard;
  if (settings.progress) request.progress = settings.progress(name);
  const double radius = setup.situation.field.ball.radius_m;
  const std::vector<TrialResult> results = RunKickTrials(*setup.simulator, request);
  for (std::size_t k = 0; k < results.size(); ++k) {
    const TrialResult& trial = results[k];
    // A kick is what the model describes when the robot stood through it and struck the ball.
    if (trial.blocked) {
      ++kick.blocked;
      kick.blocked_trials.push_back(settings.shard.Item(static_cast<int>(k)));
      continue;
    }
    if (trial.fell) {
      ++kick.fell;
      kick.fell_trials.push_back(settings.shard.Item(static_cast<int>(k)));
      continue;
    }
    if (!trial.touched) {
      ++kick.missed;
      continue;
    }
    KickObservation observation = ObservationOf(trial, radius);
    if (observation.has_roll_distance) {  // the ball lay at the situation's spot in every trial
      observation.launch_offset_m = (trial.p_F_launch - setup.state.p_F_ball).norm();
      observation.has_launch_offset = true;
    }
    kick.observations.push_back(std::move(observation));
    kick.draws.push_back(trial.draw);
    kick.trials.push_back(settings.shard.Item(static_cast<int>(k)));
  }
  return kick;
}

}  // namespace

namespace {

// The set-up, the kicks to play and the result's files; `play` plays each kick.
template <typename Play>
PhysicsCalibration Calibration(const PhysicsCalibrationSettings& settings,
                               const std::filesystem::path& models_dir, Play&& play) {
  PhysicsCalibration result;
  result.situation_file = settings.situation_file.empty()
                              ? DataFile(models_dir, DataFolder::kCalibration, settings.robot)
                              : settings.situation_file;
  const auto setup = LoadCalibrationSetup(settings, result.situation_file, models_dir);
  // The scene reads the robot's variation at every trial, so this is all it takes.
  if (settings.variation) setup->robot.spec.variation = *settings.variation;
  const std::vector<std::string> kicks =
      ChooseKicks(settings.kick, KicksWithMotion(*setup), settings.kick_field,
                  "the motions of robot '" + settings.robot + "'");
  result.physics_file = setup->physics_file;
  result.field = setup->situation.field.name;
  result.base = setup->params.robot.base;
  result.carpet_deceleration_mps2 = setup->params.carpet.rolling_deceleration_mps2;
  result.model = setup->situation.kicks;
  for (const std::string& name : kicks) {
    result.kicks.push_back(play(*setup, name));
    const KickMotion& motion = setup->robot.motions[*setup->robot.FindMotion(name)];
    result.kicks.back().clearance = FindMotionClearance(setup->robot, motion);
  }
  return result;
}

}  // namespace

PhysicsCalibration RunPhysicsCalibration(const PhysicsCalibrationSettings& settings,
                                         const std::filesystem::path& models_dir) {
  return Calibration(settings, models_dir, [&](const PhysicsSetup& setup, const std::string& name) {
    return PlayKick(setup, settings, name);
  });
}

PhysicsCalibration PlanPhysicsCalibration(const PhysicsCalibrationSettings& settings,
                                          const std::filesystem::path& models_dir) {
  return Calibration(settings, models_dir, [](const PhysicsSetup& setup, const std::string& name) {
    PhysicsKickTrials kick;
    kick.kick = name;
    kick.kick_index = *setup.situation.kicks.Find(name);
    return kick;
  });
}

std::vector<std::string> ChooseKicks(const std::string& wanted,
                                     const std::vector<std::string>& available,
                                     const std::string& field, const std::string& where) {
  if (wanted.empty()) return available;
  for (const std::string& name : available) {
    if (name == wanted) return {name};
  }
  std::string names;
  for (const std::string& name : available) names += (names.empty() ? "" : ", ") + name;
  throw InputError(field + ": no kick '" + wanted + "' in " + where + " (one of: " + names + ")");
}

}  // namespace foresight
