// How a team policy (models/team_policy.h) steers a robot: the kWalk command that walks straight
// to a point while turning to a heading, the inverse of the simulator's walk step
// (match/robot_motion.h: omnidirectional walking, the velocity clamped to the robot's limits, the
// position advanced with the heading at the start of the step, so such a command moves the robot
// along the straight line to its target, never past it).
#pragma once

#include "common/geometry.h"
#include "models/team_policy.h"

namespace foresight {

// A kWalk command that would reach p_F_target and heading face_F_rad within one step of dt_s
// (the simulator clamps it to the robot's limits: the robot then moves part of the way).
RobotCommand WalkTowards(const Pose2& pose, const Vec2& p_F_target, double face_F_rad, double dt_s);

// A kWalk command that turns on the spot towards heading_F_rad (clamped likewise).
RobotCommand TurnTowards(const Pose2& pose, double heading_F_rad, double dt_s);

// Bearing of p_F seen from `pose`, in the robot frame (0 ahead, +pi/2 left).
double BearingTo(const Pose2& pose, const Vec2& p_F);

// Heading in F from `from` towards `to`.
double HeadingTowards(const Vec2& from, const Vec2& to);

}  // namespace foresight
