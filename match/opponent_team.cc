#include "match/opponent_team.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "match/robot_motion.h"
#include "models/walk_command.h"

namespace foresight {

int RequireKick(const KickModel& kicks, const std::string& name, const std::string& file,
                const std::string& field) {
  const std::optional<int> index = kicks.Find(name);
  if (!index) {
    throw InputError(file + ": " + field + ": unknown kick '" + name + "' (the kick model has " +
                     kicks.Names() + ")");
  }
  return *index;
}

OpponentTeam::OpponentTeam(const MatchConfig& config, const KickModel& kicks,
                           const RobotParams& robot, double ball_radius_m,
                           const SimulationParams& sim)
    : config_(&config),
      clear_kick_(RequireKick(kicks, config.clear_kick, config.file.string(), "clear_kick")),
      contact_m_(robot.body_radius_m + ball_radius_m),
      grab_reach_m_(robot.grab_reach_m),
      grab_cone_rad_(robot.grab_cone_rad),
      dt_s_(sim.control_step_s),
      release_after_s_(sim.ball_holding_limit_s - robot.kick_launch_s),
      memory_(config.opponents.size()) {}

RobotCommand OpponentTeam::Clear(Memory& m, const Perception& p) const {
  const Vec2 ahead = UnitVector(p.pose.theta_rad);
  const Pose2* blocker = nullptr;
  double nearest_m = config_->clear_free_distance_m;
  auto consider = [&](const Pose2& other) {
    const Vec2 to = other.p_F - p.p_F_ball;
    const double distance = to.norm();
    if (distance >= nearest_m || distance < 1e-9) return;
    if (std::acos(std::clamp(to.dot(ahead) / distance, -1.0, 1.0)) > config_->clear_free_cone_rad) {
      return;
    }
    nearest_m = distance;
    blocker = &other;
  };
  for (std::size_t i = 0; i < p.teammates.size(); ++i) {
    if (static_cast<int>(i) != p.self) consider(p.teammates[i]);
  }
  for (const Pose2& o : p.opponents) consider(o);
  if (blocker == nullptr || p.time_s - m.holding_since_s >= release_after_s_) {
    RobotCommand kick;
    kick.kind = CommandKind::kKick;
    kick.kick_index = clear_kick_;
    return kick;
  }
  // Turn away from the blocker: the side it is not on (ties turn counter-clockwise when the
  // robot faces +x, clockwise when it faces -x, so the mirrored game turns alike).
  double side = WrapAngle(HeadingTowards(p.p_F_ball, blocker->p_F) - p.pose.theta_rad);
  if (std::abs(side) < 1e-9) side = std::cos(p.pose.theta_rad) >= 0.0 ? -1.0 : 1.0;
  RobotCommand turn;
  turn.kind = CommandKind::kWalk;
  turn.turn_radps = (side > 0.0 ? -1.0 : 1.0) * kPi / dt_s_;
  return turn;
}

RobotCommand OpponentTeam::Decide(const Perception& p) {
  RobotCommand command;
  Memory& m = memory_[static_cast<std::size_t>(p.self)];
  if (p.holding_ball && !m.was_holding) m.holding_since_s = p.time_s;
  m.was_holding = p.holding_ball;
  if (p.busy) return command;
  if (p.holding_ball) return Clear(m, p);
  const FieldBox& region = config_->opponents[static_cast<std::size_t>(p.self)].region;
  const Vec2& ball = p.p_F_ball;
  const double face_rad = HeadingTowards(p.pose.p_F, ball);
  // The ball counts as in the region when the robot can grab it from inside: a ball held one
  // body length outside the boundary would otherwise stay out of play in front of it forever.
  const double reach_m = contact_m_ + grab_reach_m_;
  if ((region.Clamp(ball) - ball).norm() > reach_m) {
    return WalkTowards(p.pose, region.Clamp(ball), face_rad, dt_s_);
  }
  const Vec2 to_ball = ball - p.pose.p_F;
  const double distance = to_ball.norm();
  if (distance <= reach_m && std::abs(BearingTo(p.pose, ball)) <= grab_cone_rad_) {
    command.kind = CommandKind::kGetBall;
    return command;
  }
  const double stop_m = contact_m_ + 0.5 * grab_reach_m_;
  const Vec2 approach = distance > stop_m ? Vec2(ball - stop_m * to_ball / distance) : p.pose.p_F;
  return WalkTowards(p.pose, region.Clamp(approach), face_rad, dt_s_);
}

}  // namespace foresight
