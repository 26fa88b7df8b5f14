// How a robot's walk command moves it in one control step (policies steer with the inverse,
// models/walk_command.h): omnidirectional walking (the AIBO walks in any direction of its frame
// while turning), the velocity scaled down along its own direction onto the ellipse of the
// gait's top speeds (forward or backward along x, sideways along y: (vx / vx_max)^2 +
// (vy / vy_max)^2 <= 1; a top speed of 0 forbids that way), the turning rate clamped. The
// position advances with the heading at the start of the step.
#pragma once

#include "common/geometry.h"
#include "models/team_policy.h"

namespace foresight {

struct WalkLimits {
  double forward_mps = 0.0;
  double turn_radps = 0.0;
  double sideways_mps = 0.0;
  double backward_mps = 0.0;
};

// The pose after walking with v_R_mps and turn_radps (both clamped to `limits`) for dt_s.
Pose2 ApplyWalk(const Pose2& pose, const Vec2& v_R_mps, double turn_radps, const WalkLimits& limits,
                double dt_s);

}  // namespace foresight
