// Drawing the samples of a hypothesis (Mellmann & Schlotter, eq. 1): sample i draws the state
// (robot pose and ball position relative to the robot, each coordinate normal with its sigma)
// and the kick noise (standard normals z_speed, z_direction) from its own numbers, keyed (seed, i):
// its seven standard normals are common/random.h's IndexedNormal 0 .. 6 of that key.
//
// Common random numbers: every candidate action of one decision (each kick, each rotation)
// uses the same draws, scaled by its own sigmas: v0 = speed + sigma_v z_speed,
// alpha = direction + sigma_alpha z_direction. Differences between candidates then come from
// the candidates, not from the luck of their samples, and the rotation search sees a
// deterministic objective.
#pragma once

#include <cstdint>
#include <vector>

#include "models/kick_model.h"
#include "models/outcome.h"
#include "models/situation.h"
#include "planner/lanes.h"

namespace foresight {

inline constexpr std::uint64_t kActionStreamDomain = 0x616374696f6e7331ULL;

struct DrawnSample {
  DrawnState state;
  double z_speed = 0.0;
  double z_direction = 0.0;
  std::uint64_t stream = 0;  // the sample's stream key, for simulators that draw more
};

DrawnSample DrawSample(const StateEstimate& estimate, std::uint64_t seed, std::uint64_t index);

// Draws samples 0 .. count-1 into `out` (resized; its storage is reused between decisions).
void DrawSamples(const StateEstimate& estimate, std::uint64_t seed, int count,
                 std::vector<DrawnSample>& out);

// Samples first .. first + kLanes - 1 in SIMD lanes (planner/lanes.h), lane l with the bits of
// DrawSample(estimate, seed, first + l).
struct SampleLanes {
  LaneBits stream;
  Lanes robot_x, robot_y, robot_theta_rad;
  Lanes ball_x, ball_y;  // p_F_ball
  Lanes z_speed, z_direction;
};
SampleLanes DrawSampleLanes(const StateEstimate& estimate, std::uint64_t seed, std::uint64_t first);
// Samples first .. first + groups * kLanes - 1 as `groups` (at most kDrawGroups) lane groups
// out[0 .. groups), each as DrawSampleLanes draws it. In lanes, the normals' fast paths of all
// groups come first and the few slow-path normals (common/random.h's IndexedNormal) are
// finished together after them.
inline constexpr int kDrawGroups = 32 / kLanes;
void DrawSampleGroups(const StateEstimate& estimate, std::uint64_t seed, std::uint64_t first,
                      int groups, SampleLanes* out);
// DrawSampleLanes's two ways, with the same bits: the draws in lanes (planner/random_lanes.h;
// what builds with SSE4.1 or more use) and DrawSample per lane (what SSE2 alone uses, being
// faster there). Both compile on every target, so the tests compare them in every build.
SampleLanes DrawSampleLanesVector(const StateEstimate& estimate, std::uint64_t seed,
                                  std::uint64_t first);
void DrawSampleGroupsVector(const StateEstimate& estimate, std::uint64_t seed, std::uint64_t first,
                            int groups, SampleLanes* out);
void DrawSampleGroupsScalar(const StateEstimate& estimate, std::uint64_t seed, std::uint64_t first,
                            int groups, SampleLanes* out);
SampleLanes DrawSampleLanesScalar(const StateEstimate& estimate, std::uint64_t seed,
                                  std::uint64_t first);

// The drawn launch of `kick` for a sample's standard normals (common random numbers: every kick
// scales the same z by its own sigmas). T is double or SIMD lanes (planner/lanes.h).
template <typename T>
T LaunchSpeed(const KickSpec& kick, T z_speed) {
  return kick.speed_mps + kick.sigma_speed_mps * z_speed;
}
template <typename T>
T LaunchDirection(const KickSpec& kick, T z_direction) {
  return kick.direction_rad + kick.sigma_direction_rad * z_direction;
}

// The concrete action of `kick` (or none, kick_index == kNoKick) turned by rotation_rad, for one
// sample. Its stream is derived from the sample's, the same for every candidate (common random
// numbers for simulators that draw more, like physics).
ConcreteAction MakeAction(const KickModel& kicks, int kick_index, double rotation_rad,
                          const DrawnSample& sample);

}  // namespace foresight
