#include "models/walk_command.h"

#include <cmath>

namespace foresight {

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

RobotCommand TurnTowards(const Pose2& pose, double heading_F_rad, double dt_s) {
  RobotCommand command;
  command.kind = CommandKind::kWalk;
  command.turn_radps = WrapAngle(heading_F_rad - pose.theta_rad) / dt_s;
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
