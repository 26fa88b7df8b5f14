#include "match/robot_motion.h"

#include <algorithm>

namespace foresight {

Pose2 ApplyWalk(const Pose2& pose, const Vec2& v_R_mps, double turn_radps, const WalkLimits& limits,
                double dt_s) {
  Vec2 v = v_R_mps;
  const double speed = v.norm();
  if (speed > limits.speed_mps) v *= limits.speed_mps / speed;
  const double turn = std::clamp(turn_radps, -limits.turn_radps, limits.turn_radps);
  Pose2 next = pose;
  next.p_F = pose.ToField(v * dt_s);
  next.theta_rad = WrapAngle(pose.theta_rad + turn * dt_s);
  return next;
}

RobotCommand WalkTowards(const Pose2& pose, const Vec2& p_F_target, double face_F_rad,
                         double dt_s) {
  RobotCommand command;
  command.kind = CommandKind::kWalk;
  const Vec2 d_F = p_F_target - pose.p_F;
  double s, c;
  SinCos(pose.theta_rad, &s, &c);
  command.v_R_mps = Vec2(c * d_F.x() + s * d_F.y(), -s * d_F.x() + c * d_F.y()) / dt_s;
  command.turn_radps = WrapAngle(face_F_rad - pose.theta_rad) / dt_s;
  return command;
}

double BearingTo(const Pose2& pose, const Vec2& p_F) {
  return WrapAngle(HeadingTowards(pose.p_F, p_F) - pose.theta_rad);
}

double HeadingTowards(const Vec2& from, const Vec2& to) {
  const Vec2 d = to - from;
  return std::atan2(d.y(), d.x());
}

}  // namespace foresight
