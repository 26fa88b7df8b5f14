// The settings of a kick motion search (tools/motion_search.h), read from a JSON file
// (models/motion_search/*.json): which kick of which robot, on which base, the rounds of the
// search (how many candidates, how many trials each, how far a candidate strays from its
// centre), the refusal rules and the objective. Every number is the file's; the file says why.
//
// {
//   "notes": "why these numbers",
//   "situation": "nao",              a calibration situation (models/calibration/<name>.json or a path)
//   "kicks": "nao_calibrated",       optional: the kick model (models/kicks/<name>.json or a path)
//   "kick": "forward_long",          the kick whose motion is searched
//   "start": "start/x.json",         optional: the first round's centre, a motion file (a path
//                                    from this file's folder); absent: the robot's shipped motion
//   "base": "floating",              fixed | floating
//   "seed": 1,
//   "rounds": [{"candidates": 200, "trials": 20, "keyframe_sigma_deg": 8, "time_sigma_rel": 0.1,
//               "balance_sigma_deg": 1, "max_tilt_deg": 22.5}, ...],   max_tilt_deg optional
//   "constraints": {"min_clearance_m": 0.005, "max_speed_share": 1.0, "max_fall_share": 0.0,
//                   "max_duration_s": 3.0, "max_tilt_deg": 22.5},   max_tilt_deg optional
//   "objective": {"target_speed_mps": 1.6, "target_direction_deg": 0, ...},
//   "keep": 5
// }
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "models/physics_params.h"

namespace foresight {

// One round: `candidates` motions drawn around the centre (the start motion in the first round,
// the best candidate of the round before in the others), each played `trials` times.
struct SearchRound {
  int candidates = 0;
  int trials = 0;
  double keyframe_sigma_rad = 0.0;  // per joint and inner keyframe, normal
  double time_sigma_rel = 0.0;      // per segment duration, relative, normal
  double balance_sigma_rad = 0.0;   // one draw added to every balance offset's magnitude
  // Optional: this round's tilt refusal (SearchConstraints::max_tilt_rad) instead of the
  // constraints'. A tilt refusal comes after a candidate's trials, so a limit in the last round
  // only ranks the same candidates as the search without it, leaving out those that swayed:
  // how the shipped side kicks were picked.
  std::optional<double> max_tilt_rad;
};

// A candidate is refused (not scored) when it breaks one of these.
struct SearchConstraints {
  double min_clearance_m = 0.0;   // lowest point of the body over the motion's targets
  double max_speed_share = 1.0;   // peak joint speed / URDF limit at the fastest playback
  double max_fall_share = 0.0;    // trials in which the robot fell, share
  double max_duration_s = 0.0;    // the motion as written, after FitToSpeedLimit slowed it
  // Optional: the torso's largest tilt over a candidate's trials (floating base); a candidate
  // that stands but sways past it has no margin left against falling. Not given: no limit.
  double max_tilt_rad = std::numeric_limits<double>::infinity();
};

// Lower is better: |mean launch - target| (m/s) plus weighted penalties.
struct SearchObjective {
  double target_speed_mps = 0.0;
  double target_direction_rad = 0.0;
  double speed_sd_max_mps = 0.0;     // sd_weight per m/s of launch sd above it
  double sd_weight = 0.0;
  double min_speed_mps = 0.0;        // low_weight per share of launches below it
  double low_weight = 0.0;
  double direction_max_rad = 0.0;    // direction_weight per rad of mean direction error beyond it
  double direction_weight = 0.0;
  double miss_weight = 0.0;          // per share of trials that never launched the ball
  double fall_weight = 0.0;          // per share of trials in which the robot fell
};

struct MotionSearchSettings {
  std::filesystem::path file;           // where they were read
  std::filesystem::path situation_file;  // resolved
  std::filesystem::path kicks_file;      // resolved; empty: the situation's
  std::filesystem::path start_file;      // resolved; empty: the robot's shipped motion
  std::string kick;
  RobotBase base = RobotBase::kFloating;
  std::uint64_t seed = 1;
  std::vector<SearchRound> rounds;
  SearchConstraints constraints;
  SearchObjective objective;
  int keep = 1;  // best candidates printed per round and written at the end
};

// Throws InputError "FILE: FIELD: problem" on a bad file; references resolve against
// models_dir like a situation's.
MotionSearchSettings LoadMotionSearchSettings(const std::filesystem::path& file,
                                              const std::filesystem::path& models_dir);

}  // namespace foresight
