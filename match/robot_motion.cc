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

}  // namespace foresight
