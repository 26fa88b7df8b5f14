// A robot's kicks played in physics from its calibration situation, trial by trial, as
// `foresight calibrate` fits them and the calibration checks of `foresight check` test them.
// One loop for both, so that a check reproduces exactly the numbers a calibration would fit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/shard.h"
#include "models/kick_model.h"
#include "physics/motion_clearance.h"
#include "physics/trial.h"
#include "validation/calibration.h"

namespace foresight {

struct PhysicsCalibrationSettings {
  std::string robot;
  std::string kick;                      // the one kick to play; empty: every kick with a motion
  std::string kick_field = "--kick";     // names `kick` in messages
  int trials = 1000;                     // per kick
  std::uint64_t seed = 1;                // kick k's trials use CalibrationSeed(seed, k)
  int threads = 0;                       // <= 0: all cores
  std::filesystem::path situation_file;  // empty: MODELS/calibration/<robot>.json
  std::filesystem::path kicks_file;      // empty: the situation's kick model
  std::filesystem::path physics_file;    // empty: MODELS/physics/<field>.json
  std::optional<RobotBase> base;         // replaces the physics file's robot base
  std::optional<TrialVariation> variation;  // replaces robot.json's trial_variation
  // Called before each kick's trials with the kick's name; what it returns sees (done, total).
  std::function<std::function<void(int, int)>(const std::string& kick)> progress;
  // Only trials i with shard.Owns(i) of every kick run (validation/calibration_shard.h).
  Shard shard;
};

// One kick's trials: an observation and the physical causes drawn for each trial that touched
// the ball, in trial order, and how many did not.
struct PhysicsKickTrials {
  std::string kick;
  int kick_index = 0;  // into PhysicsCalibration::model
  std::vector<KickObservation> observations;
  std::vector<TrialDraw> draws;
  std::vector<int> trials;  // the trial index of each observation
  int missed = 0;  // the robot did not touch the ball (and did not fall, and was not blocked)
  // The robot fell (floating base), whether before or after it launched the ball: a fall is
  // counted here and never observed, so a launch the robot fell after is not in the fit (the
  // kick model describes kicks the robot stands through; the report prints the count).
  int fell = 0;
  std::vector<int> fell_trials;  // the trial index of each fall, ascending
  // The robot could not take its stance (floating base: a post, net or obstacle robot stood
  // there) and the kick was not played. Left out of the fit as a miss is: it says nothing
  // about the kick. The trial index of each, ascending.
  int blocked = 0;
  std::vector<int> blocked_trials;
  MotionClearance clearance;  // of the kick's motion (physics/motion_clearance.h)
};

struct PhysicsCalibration {
  std::filesystem::path situation_file;  // as loaded (the default filled in)
  std::filesystem::path physics_file;
  std::string field;                      // the situation's field
  RobotBase base = RobotBase::kFixed;     // the kicking robot's, as played
  double carpet_deceleration_mps2 = 0.0;  // the carpet's truth
  KickModel model;                        // the situation's kick model (after kicks_file)
  std::vector<PhysicsKickTrials> kicks;   // in the model's order
};

// Throws InputError when a file is bad, the kick model is for another robot or `kick` has no
// motion.
PhysicsCalibration RunPhysicsCalibration(const PhysicsCalibrationSettings& settings,
                                         const std::filesystem::path& models_dir);

// The same checks and files without playing: the kicks named, their trials empty (a merge of
// shards fills them in).
PhysicsCalibration PlanPhysicsCalibration(const PhysicsCalibrationSettings& settings,
                                          const std::filesystem::path& models_dir);

// `wanted` from `available`, or all of them when `wanted` is empty; InputError
// "FIELD: no kick 'X' in WHERE (one of: ...)" when it is not there.
std::vector<std::string> ChooseKicks(const std::string& wanted,
                                     const std::vector<std::string>& available,
                                     const std::string& field, const std::string& where);

}  // namespace foresight
