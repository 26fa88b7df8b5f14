// How a robot's walk command moves it in one control step, and the inverse that policies use to
// walk to a point: omnidirectional walking (the AIBO walks in any direction of its frame while
// turning), the velocity scaled down to the speed limit along its own direction, the turning
// rate clamped. The position advances with the heading at the start of the step, so a command
// made by WalkTowards moves the robot along the straight line to its target, never past it.
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

// A kWalk command that would reach p_F_target and heading face_F_rad within one step of dt_s
// (the simulator clamps it to the robot's limits: the robot then moves part of the way).
RobotCommand WalkTowards(const Pose2& pose, const Vec2& p_F_target, double face_F_rad, double dt_s);

// Bearing of p_F seen from `pose`, in the robot frame (0 ahead, +pi/2 left).
double BearingTo(const Pose2& pose, const Vec2& p_F);
// Heading in F from `from` towards `to`.
double HeadingTowards(const Vec2& from, const Vec2& to);

}  // namespace foresight
