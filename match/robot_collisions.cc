#include "match/robot_collisions.h"

#include <cmath>

namespace foresight {

bool MoveAllowed(const MatchWorld& world, const MoveRules& rules, std::size_t robot,
                 const Pose2& pose) {
  if (std::abs(pose.p_F.x()) > rules.x_max_m || std::abs(pose.p_F.y()) > rules.y_max_m) {
    return false;
  }
  if (const std::optional<FieldBox>& region = rules.regions[robot];
      region && !region->Contains(pose.p_F)) {
    // Outside its region (back from a penalty at the touchline) a robot may only walk back in.
    const Vec2& from = world.robots[robot].pose.p_F;
    const double from_m = (from - region->Clamp(from)).norm();
    if (from_m == 0.0 || (pose.p_F - region->Clamp(pose.p_F)).norm() >= from_m) return false;
  }
  const bool holding = world.ball.holder == static_cast<int>(robot);
  const Vec2 held_ball = pose.ToField(Vec2(rules.contact_m, 0.0));
  for (std::size_t j = 0; j < world.robots.size(); ++j) {
    if (j == robot) continue;
    const Vec2& other = world.robots[j].pose.p_F;
    if ((other - pose.p_F).norm() < 2.0 * rules.body_radius_m) return false;
    // A held ball is part of the holder: it may not be pushed into another body either (nor
    // deeper, when it already touches one: moving it away is allowed).
    const double ball_gap_m = (other - held_ball).norm();
    if (holding && ball_gap_m < rules.contact_m && ball_gap_m < (other - world.ball.p_F).norm()) {
      return false;
    }
  }
  return true;
}

void ResolveMoves(MatchWorld& world, const MoveRules& rules, const std::vector<Pose2>& proposed) {
  for (std::size_t i = 0; i < proposed.size(); ++i) {
    RobotState& r = world.robots[i];
    const Pose2 from = r.pose;
    if (MoveAllowed(world, rules, i, proposed[i])) {
      r.pose = proposed[i];
      continue;
    }
    Pose2 slid = proposed[i];
    for (std::size_t j = 0; j < world.robots.size(); ++j) {
      const Vec2 gap = world.robots[j].pose.p_F - slid.p_F;
      if (j == i || gap.norm() >= 2.0 * rules.body_radius_m) continue;
      const Vec2 n = (world.robots[j].pose.p_F - from.p_F).normalized();
      Vec2 move = slid.p_F - from.p_F;
      if (move.dot(n) > 0.0) move -= move.dot(n) * n;
      slid.p_F = from.p_F + move;
    }
    const Pose2 turned{from.p_F, proposed[i].theta_rad};
    if (MoveAllowed(world, rules, i, slid)) {
      r.pose = slid;
    } else if (MoveAllowed(world, rules, i, turned)) {
      r.pose = turned;
    }
  }
}

}  // namespace foresight
