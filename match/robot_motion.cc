#include "match/robot_motion.h"

#include <algorithm>
#include <cmath>

namespace foresight {

Pose2 ApplyWalk(const Pose2& pose, const Vec2& v_R_mps, double turn_radps, const WalkLimits& limits,
                double dt_s) {
  Vec2 v = v_R_mps;
  const double along_max = v.x() >= 0.0 ? limits.forward_mps : limits.backward_mps;
  if (!(along_max > 0.0)) v.x() = 0.0;
  if (!(limits.sideways_mps > 0.0)) v.y() = 0.0;
  const double ex = v.x() != 0.0 ? v.x() / along_max : 0.0;
  const double ey = v.y() != 0.0 ? v.y() / limits.sideways_mps : 0.0;
  const double over = std::sqrt(ex * ex + ey * ey);
  if (over > 1.0) v /= over;
  const double turn = std::clamp(turn_radps, -limits.turn_radps, limits.turn_radps);
  Pose2 next = pose;
  next.p_F = pose.ToField(v * dt_s);
  next.theta_rad = WrapAngle(pose.theta_rad + turn * dt_s);
  return next;
}

}  // namespace foresight
