// How far a kick of the coarse model carries the ball on open carpet (planner/ball_roll.h). The
// launch speed is v ~ N(v0, sigma_v^2) (models/kick_model.h) and the ball rests L + v^2 / (2 a)
// from the kick, L the kick's launch offset, so
//   mean roll       E[d] = L + (v0^2 + sigma_v^2) / (2 a)      (E[v^2] = v0^2 + sigma_v^2)
//   roll at z sd    d(z) = L + max(0, v0 + z sigma_v)^2 / (2 a)
// d(z) is the roll that a share 1 - Phi(z) of the kicks exceeds (d grows with v), e.g. z = 2: one
// kick in 44. A case's ball path and its free-path corridor end where the kick ends (cbr/): at
// the roll at reach_sigmas sd (models/cbr/retrieval.json).
#pragma once

#include <algorithm>

#include "models/kick_model.h"
#include "planner/ball_roll.h"

namespace foresight {

inline double MeanRollDistance(const KickSpec& kick, double deceleration_mps2) {
  return kick.launch_offset_m + StopDistance(kick.speed_mps, deceleration_mps2) +
         StopDistance(kick.sigma_speed_mps, deceleration_mps2);
}

inline double RollDistanceAtSigmas(const KickSpec& kick, double deceleration_mps2, double z) {
  const double speed_mps = std::max(0.0, kick.speed_mps + z * kick.sigma_speed_mps);
  return kick.launch_offset_m + StopDistance(speed_mps, deceleration_mps2);
}

}  // namespace foresight
