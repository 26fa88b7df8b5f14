// Running many physics trials of one kick in parallel, and what they add up to.
//
// Trial i draws from stream StreamKey(seed, i, kPhysicsTrialDomain) and writes result slot i, so
// the results are the same whatever the thread count (docs/ARCHITECTURE.md, "Randomness and
// determinism").
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "common/shard.h"
#include "physics/physics_simulator.h"

namespace foresight {

inline constexpr std::uint64_t kPhysicsTrialDomain = 0x7068797369637331ULL;

struct KickTrialsRequest {
  DrawnState state;           // the situation's mean state: where the ball really is
  int kick_index = 0;         // into the kick model
  double rotation_rad = 0.0;  // turn around the ball before the kick
  int trials = 0;
  std::uint64_t seed = 0;
  int threads = 0;  // <= 0: all cores
  bool record_trace = false;
  double scene_rate_hz = 0.0;  // > 0: every trial records its scene at this rate
  std::function<void(int, int)> progress;  // (done, total)
  // Only trials i with shard.Owns(i) run; the results hold those, in trial order.
  Shard shard;
};

std::vector<TrialResult> RunKickTrials(const PhysicsSimulator& simulator,
                                       const KickTrialsRequest& request);

struct TrialSummary {
  int trials = 0;
  std::array<int, kCategoryCount> categories{};
  std::array<int, 5> first_contacts{};  // indexed by Contact
  int touched = 0;
  int launched = 0;
  int settled = 0;
  int fell = 0;                  // the robot fell (floating base)
  int blocked = 0;               // the robot could not take its stance (floating base)
  double max_tilt_rad = 0.0;     // the torso's largest tilt over all trials (floating base)
  // Trials whose first placement draw put the ball inside the robot, and the rejected draws in
  // all (trial.h: such draws are drawn again).
  int placement_redrawn = 0;
  int placement_redraws = 0;
  Vec2 rest_mean_F{0.0, 0.0};
  Vec2 rest_sd_F{0.0, 0.0};            // per axis, sample standard deviation
  double launch_speed_mean_mps = 0.0;  // over the touched trials
  double launch_speed_sd_mps = 0.0;
  double launch_direction_mean_rad = 0.0;  // circular mean, intended robot frame
  double launch_direction_sd_rad = 0.0;    // circular standard deviation sqrt(-2 ln R)
  double time_mean_s = 0.0;
};

TrialSummary Summarize(std::span<const TrialResult> results);

}  // namespace foresight
