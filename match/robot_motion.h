// How a robot's walk command moves it in one control step (policies steer with the inverse,
// models/walk_command.h): omnidirectional walking (the AIBO walks in any direction of its frame
// while turning), the velocity scaled down to the speed limit along its own direction, the
// turning rate clamped. The position advances with the heading at the start of the step.
#pragma once

#include "common/geometry.h"
#include "models/team_policy.h"

namespace foresight {

struct WalkLimits {
  double speed_mps = 0.0;
  double turn_radps = 0.0;
};

// The pose after walking with v_R_mps and turn_radps (both clamped to `limits`) for dt_s.
Pose2 ApplyWalk(const Pose2& pose, const Vec2& v_R_mps, double turn_radps, const WalkLimits& limits,
                double dt_s);

}  // namespace foresight
