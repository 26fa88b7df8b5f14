#include "match/opponent_team.h"

#include <cmath>

#include "common/error.h"
#include "match/robot_motion.h"

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
                           const RobotParams& robot, double ball_radius_m, double control_step_s)
    : config_(&config),
      clear_kick_(RequireKick(kicks, config.clear_kick, config.file.string(), "clear_kick")),
      contact_m_(robot.body_radius_m + ball_radius_m),
      grab_reach_m_(robot.grab_reach_m),
      grab_cone_rad_(robot.grab_cone_rad),
      dt_s_(control_step_s) {}

RobotCommand OpponentTeam::Decide(const Perception& p) {
  RobotCommand command;
  if (p.busy) return command;
  if (p.holding_ball) {
    command.kind = CommandKind::kKick;
    command.kick_index = clear_kick_;
    return command;
  }
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
  if (distance <= reach_m &&
      std::abs(BearingTo(p.pose, ball)) <= grab_cone_rad_) {
    command.kind = CommandKind::kGetBall;
    return command;
  }
  const double stop_m = contact_m_ + 0.5 * grab_reach_m_;
  const Vec2 approach = distance > stop_m ? Vec2(ball - stop_m * to_ball / distance) : p.pose.p_F;
  return WalkTowards(p.pose, region.Clamp(approach), face_rad, dt_s_);
}

}  // namespace foresight
