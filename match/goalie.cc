#include "match/goalie.h"

#include <cmath>

#include "models/walk_command.h"
#include "planner/ball_roll.h"

namespace foresight {

RobotCommand GoForBallInRegion(const Perception& p, const FieldBox& region, double contact_m,
                               double grab_reach_m, double grab_cone_rad, double dt_s) {
  const Vec2& ball = p.p_F_ball;
  const double face_rad = HeadingTowards(p.pose.p_F, ball);
  const Vec2 to_ball = ball - p.pose.p_F;
  const double distance = to_ball.norm();
  if (distance <= contact_m + grab_reach_m && std::abs(BearingTo(p.pose, ball)) <= grab_cone_rad) {
    RobotCommand grab;
    grab.kind = CommandKind::kGetBall;
    return grab;
  }
  const double stop_m = contact_m + 0.5 * grab_reach_m;
  const Vec2 approach = distance > stop_m ? Vec2(ball - stop_m * to_ball / distance) : p.pose.p_F;
  return WalkTowards(p.pose, region.Clamp(approach), face_rad, dt_s);
}

Goalie::Goalie(const GoalieParams& params, const FieldBox& region, const FieldSpec& field,
               const RobotParams& robot, double rolling_deceleration_mps2, double control_step_s)
    : params_(params),
      region_(region),
      goal_line_x_m_(field.HalfLength()),
      contact_m_(robot.body_radius_m + field.ball.radius_m),
      grab_reach_m_(robot.grab_reach_m),
      grab_cone_rad_(robot.grab_cone_rad),
      block_half_span_m_(robot.block_half_span_m),
      deceleration_mps2_(rolling_deceleration_mps2),
      dt_s_(control_step_s) {}

void Goalie::Delayed(double now_s, Vec2& p_F_ball, Vec2& v_F_ball) const {
  const double at_s = now_s - params_.latency_s + 1e-9;
  std::size_t k = 0;
  while (k + 1 < seen_.size() && seen_[k + 1].time_s <= at_s) ++k;
  p_F_ball = seen_[k].p_F_ball;
  v_F_ball = Vec2(0.0, 0.0);
  if (k > 0 && seen_[k].time_s > seen_[k - 1].time_s) {
    v_F_ball = (seen_[k].p_F_ball - seen_[k - 1].p_F_ball) / (seen_[k].time_s - seen_[k - 1].time_s);
  }
}

bool Goalie::ShotToBlock(const Perception& p, const Vec2& ball, const Vec2& velocity) const {
  const double speed = velocity.norm();
  const double own_goal_x = -p.attack_sign * goal_line_x_m_;
  if (!(speed > 1e-6) || velocity.x() * (own_goal_x - ball.x()) <= 0.0) return false;
  const double to_line_x = p.pose.p_F.x() - ball.x();
  if (to_line_x * velocity.x() <= 0.0) return false;  // already past the goalie's line
  const double t_line_s = to_line_x / velocity.x();     // at constant speed
  const double path_m = speed * t_line_s;
  if (path_m > StopDistance(speed, deceleration_mps2_)) return false;  // stops before the line
  const double arrive_s = TimeToRoll(speed, deceleration_mps2_, path_m);
  const double y_cross = ball.y() + velocity.y() * t_line_s;
  return std::abs(y_cross - p.pose.p_F.y()) <= block_half_span_m_ &&
         arrive_s <= params_.block_earliest_s;
}

RobotCommand Goalie::Guard(const Perception& p, const Vec2& ball) const {
  const Vec2 goal(-p.attack_sign * goal_line_x_m_, 0.0);
  const double guard_x = goal.x() + p.attack_sign * params_.guard_distance_m;
  // The point of the ball-to-goal-centre line at guard_x (the goal centre's y when the ball lies
  // level with the guard line or behind it).
  const double along = (guard_x - goal.x()) / (ball.x() - goal.x());
  const double guard_y = along > 0.0 && along < 1.0 ? along * ball.y() : 0.0;
  const Vec2 target = region_.Clamp(Vec2(guard_x, guard_y));
  RobotCommand walk = WalkTowards(p.pose, target, HeadingTowards(p.pose.p_F, ball), dt_s_);
  const double speed = walk.v_R_mps.norm();
  if (speed > params_.walk_speed_mps) walk.v_R_mps *= params_.walk_speed_mps / speed;
  return walk;
}

RobotCommand Goalie::Decide(const Perception& p) {
  seen_.push_back({p.time_s, p.p_F_ball});
  // Keep the samples from just before the delayed time on.
  while (seen_.size() > 2 && seen_[1].time_s < p.time_s - params_.latency_s - dt_s_) {
    seen_.pop_front();
  }
  Vec2 ball, velocity;
  Delayed(p.time_s, ball, velocity);
  if (p.busy) return {};
  if (p.time_s - last_block_s_ >= params_.block_refractory_s && ShotToBlock(p, ball, velocity)) {
    last_block_s_ = p.time_s;
    RobotCommand block;
    block.kind = CommandKind::kBlock;
    return block;
  }
  if ((region_.Clamp(ball) - ball).norm() <= contact_m_ + grab_reach_m_) {
    Perception delayed = p;
    delayed.p_F_ball = ball;
    return GoForBallInRegion(delayed, region_, contact_m_, grab_reach_m_, grab_cone_rad_, dt_s_);
  }
  return Guard(p, ball);
}

}  // namespace foresight
