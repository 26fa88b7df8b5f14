// The DG configuration's goalie as a robot (Ros et al. 2009, sec. 5.1.2: it stays in the penalty
// area; sec. 5.1.4: "block: the goalie stops or kicks the ball"), after the rUNSWift 2005 goalie
// (robot/PyCode/pGoalie.py, sBlock.py): figures in MatchConfig::goalie and RobotParams' block.
//
// It sees the ball latency_s late: every decision uses the ball it perceived latency_s ago and
// the ball's velocity from the two samples around then. In order:
//  - block: when that ball rolls towards its goal, will reach the goalie's line (the line through
//    the goalie parallel to the goal line) before it stops (v^2 / 2a), crosses it within the
//    block's half span of the goalie, and arrives within
//    block_earliest_s, it blocks (CommandKind::kBlock: down, held, up again; the simulator
//    spreads its body), at most once every block_refractory_s;
//  - clear: a ball in its region (or within grabbing reach of it) that is not such a shot: it
//    goes for the ball as a defender does (GoForBallInRegion);
//  - guard: otherwise it walks, at most walk_speed_mps, to the point of the line from the ball to
//    its goal's centre guard_distance_m in front of the goal line (clamped to its region), facing
//    the ball.
#pragma once

#include <deque>

#include "match/match_config.h"
#include "models/field_spec.h"
#include "models/team_policy.h"

namespace foresight {

// Walk to the point in front of the ball from which the robot can grab it (clamped to `region`)
// and grab it once it lies within reach in front: how every opponent goes for the ball.
RobotCommand GoForBallInRegion(const Perception& p, const FieldBox& region, double contact_m,
                               double grab_reach_m, double grab_cone_rad, double dt_s);

class Goalie {
 public:
  Goalie(const GoalieParams& params, const FieldBox& region, const FieldSpec& field,
         const RobotParams& robot, double rolling_deceleration_mps2, double control_step_s);
  // The command of a goalie that is free and does not hold the ball.
  RobotCommand Decide(const Perception& p);

 private:
  struct Seen {
    double time_s = 0.0;
    Vec2 p_F_ball{0.0, 0.0};
  };
  // The ball latency_s ago and its velocity then.
  void Delayed(double now_s, Vec2& p_F_ball, Vec2& v_F_ball) const;
  bool ShotToBlock(const Perception& p, const Vec2& ball, const Vec2& velocity) const;
  RobotCommand Guard(const Perception& p, const Vec2& ball) const;

  GoalieParams params_;
  FieldBox region_;
  double goal_line_x_m_;  // |x| of the goal line
  double contact_m_;
  double grab_reach_m_;
  double grab_cone_rad_;
  double block_half_span_m_;
  double deceleration_mps2_;
  double dt_s_;
  std::deque<Seen> seen_;
  double last_block_s_ = -1e9;
};

}  // namespace foresight
