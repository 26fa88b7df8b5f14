#include "cbr/case_actions.h"

#include <cmath>

#include "cbr/problem.h"
#include "cbr/similarity.h"
#include "common/geometry.h"
#include "models/walk_command.h"

namespace foresight {

namespace {

RobotCommand Stand() {
  return RobotCommand{};
}

RobotCommand GetBall() {
  RobotCommand c;
  c.kind = CommandKind::kGetBall;
  return c;
}

bool Near(const Vec2& a, const Vec2& b, double tolerance_m) {
  return (a - b).norm() <= tolerance_m;
}

// Whether the actions before `action` leave the robot where the case adapted it (waits and
// turns on the spot move no robot).
bool StillAtAdaptedSpot(const std::vector<CaseAction>& actions, std::size_t action) {
  for (std::size_t i = 0; i < action; ++i) {
    if (actions[i].type != ActionType::kWait && actions[i].type != ActionType::kTurn) return false;
  }
  return true;
}

// A receiver awaiting its pass. Under dependent positioning it executes before it has reached
// its adapted position (sec. 4.2), and the pass goes to that position (sec. 3.3.1: the ball
// path is computed from the case's positions; Fig. 13a: "robot B moves towards the front to
// receive the ball"): until the pass is made it walks on to it, facing the ball, unless an
// earlier action of its own took it elsewhere; there it turns to face the ball.
RobotCommand AwaitPass(const CasePlay& play, int me, const std::vector<CaseAction>& actions,
                       std::size_t action, const Perception& p, double tolerance_m, double dt_s) {
  const double face_ball = HeadingTowards(p.pose.p_F, p.p_F_ball);
  const Vec2& spot = play.adapted_F[static_cast<std::size_t>(me)];
  if (StillAtAdaptedSpot(actions, action) && !Near(p.pose.p_F, spot, tolerance_m)) {
    return WalkTowards(p.pose, spot, face_ball, dt_s);
  }
  return TurnTowards(p.pose, face_ball, dt_s);
}

// The heading a kick or pass is aimed at (the trajectory's end, or the goal), for the robot
// holding the ball at p_F_ball.
double AimHeading(const FuzzyTrajectory* trajectory, const KickSpec& kick, const Perception& p,
                  const ActionContext& ctx) {
  const Vec2 aim_at = trajectory ? trajectory->aim_F
                                 : Vec2(p.attack_sign * ctx.retrieval->goal_x_m, 0.0);
  return HeadingTowards(p.p_F_ball, aim_at) - kick.direction_rad;
}

// Where the held ball will leave from once the robot faces `heading`: the ball sits at the
// holder's front and turns with it, at its present distance from the robot's centre.
Vec2 LaunchPoint(const Perception& p, double heading) {
  return p.pose.p_F + (p.p_F_ball - p.pose.p_F).norm() * UnitVector(heading);
}

// A kick or pass: aim along `trajectory` with kick `kick_index`, then kick.
ActionStep AimAndKick(const FuzzyTrajectory* trajectory, int kick_index, ActionProgress& s,
                      const Perception& p, const ActionContext& ctx) {
  ActionStep step;
  const KickSpec& kick = ctx.kicks->kicks[static_cast<std::size_t>(kick_index)];
  const double heading = AimHeading(trajectory, kick, p, ctx);
  if (trajectory) {
    // The free-path test (sec. 3.3.1) on the trajectory the ball will take: from where it leaves
    // once the robot has turned to aim, not from where the turn has it now (a receiver holds the
    // pass at its side until it has turned, and the corridor from there swept past opponents
    // the kick's own corridor misses).
    const Vec2 launch = LaunchPoint(p, heading);
    CaseBallPath now;
    now.count = 1;
    const KickTrajectory& widths = ctx.retrieval->TrajectoryFor(kick.name);
    now.trajectories[0] =
        trajectory->knee_m > 0.0
            ? MakeKickTrajectory(launch, trajectory->aim_F, widths, *ctx.retrieval)
            : MakeTrajectory(launch, trajectory->aim_F, widths, *ctx.retrieval);
    for (const Pose2& o : p.opponents) {  // one at a time: no copy of the positions per step
      if (!CheckFreePath(now, std::span<const Vec2>(&o.p_F, 1), ctx.retrieval->thr_trajectory)
               .free) {
        step.abort = AbortReason::kPathBlocked;
        return step;
      }
    }
  }
  const double error = WrapAngle(heading - p.pose.theta_rad);
  if (std::abs(error) <= ctx.aim_tolerance_rad ||
      p.time_s - s.holding_since_s >= ctx.release_after_s) {
    step.command.kind = CommandKind::kKick;
    step.command.kick_index = kick_index;
    s.kicking = true;
    return step;
  }
  step.command = TurnTowards(p.pose, heading, ctx.control_step_s);
  return step;
}

// Whether the dribble must end now to leave the time to aim the robot's next kick or pass.
bool TimeToAim(const CasePlay& play, int me, const ActionProgress& s, const Perception& p,
               const ActionContext& ctx) {
  const auto& actions = play.c->teammates[static_cast<std::size_t>(me)].actions;
  if (s.action + 1 >= actions.size() || ctx.dribble_turn_radps <= 0.0) return false;
  const CaseAction& next = actions[s.action + 1];
  if (next.type != ActionType::kKick && next.type != ActionType::kPass) return false;
  const int kick_index = ctx.kicks->Find(next.kick).value_or(0);
  const KickSpec& kick = ctx.kicks->kicks[static_cast<std::size_t>(kick_index)];
  const double turn =
      std::abs(WrapAngle(AimHeading(play.KickTrajectory(me, s.kicks_done), kick, p, ctx) -
                         p.pose.theta_rad));
  const double left_s = ctx.release_after_s - (p.time_s - s.holding_since_s);
  return left_s <= turn / ctx.dribble_turn_radps + ctx.control_step_s;
}

void Advance(ActionProgress& s) {
  ++s.action;
  s.kicking = false;
  s.passer_had_ball = false;
}

}  // namespace

bool OpponentHasBall(const Perception& p, const ActionContext& ctx) {
  const double reach =
      ctx.retrieval->opponent_radius_m + ctx.retrieval->ball_radius_m + ctx.team->ball_lost_margin_m;
  for (const Pose2& o : p.opponents) {
    if ((o.p_F - p.p_F_ball).norm() <= reach) return true;
  }
  return false;
}

bool BallLeftScope(const CasePlay& play, const Perception& p, const ActionContext& ctx) {
  Problem now;
  now.p_F_ball = p.p_F_ball - play.p_F_ball + play.c->p_F_ball;  // in the case's frame
  return !(BallSimilarity(now, *play.c) > ctx.retrieval->thr_ball);
}

RobotCommand KeepClose(const Perception& p, double keep_close_m, double dt_s) {
  const Vec2 from_ball = p.pose.p_F - p.p_F_ball;
  const double d = from_ball.norm();
  const Vec2 away = d > 1e-9 ? Vec2(from_ball / d) : UnitVector(p.pose.theta_rad + kPi);
  const Vec2 target = p.p_F_ball + keep_close_m * away;
  const double face = HeadingTowards(target, p.p_F_ball);
  return WalkTowards(p.pose, target, face, dt_s);
}

ActionStep StepActions(const CasePlay& play, int me, ActionProgress& s, const Perception& p,
                       const ActionContext& ctx) {
  const auto& actions = play.c->teammates[static_cast<std::size_t>(me)].actions;
  if (p.holding_ball && !s.was_holding) s.holding_since_s = p.time_s;
  s.was_holding = p.holding_ball;
  ActionStep step;
  if (p.busy) return step;  // grabbing or kicking: the command would be ignored
  const double dt = ctx.control_step_s;
  const double tol = ctx.team->arrive_tolerance_m;
  const double face_ball = HeadingTowards(p.pose.p_F, p.p_F_ball);
  // Actions that are done at once fall through to the next in the same step.
  for (int guard = 0; guard <= static_cast<int>(actions.size()); ++guard) {
    if (s.action >= actions.size()) {
      step.finished = true;
      step.command = Stand();
      return step;
    }
    const CaseAction& a = actions[s.action];
    switch (a.type) {
      case ActionType::kWait:
        Advance(s);
        continue;
      case ActionType::kGetBall:
        if (p.holding_ball) {
          Advance(s);
          continue;
        }
        if (OpponentHasBall(p, ctx)) {
          step.abort = AbortReason::kBallLost;
        } else if (me == play.getter && s.action == 0 && BallLeftScope(play, p, ctx)) {
          step.abort = AbortReason::kBallMoved;
        }
        step.command = GetBall();
        return step;
      case ActionType::kReceive: {
        if (p.holding_ball) {
          ++s.receives_done;
          Advance(s);
          continue;
        }
        const int passer = play.RobotOfId(a.teammate);
        if (passer >= 0 && passer < static_cast<int>(p.teammates.size())) {
          const bool near = Near(p.p_F_ball, p.teammates[static_cast<std::size_t>(passer)].p_F,
                                 ctx.team->pass_seen_m);
          if (near) s.passer_had_ball = true;
          // A receiver that adopted the case late never saw the passer with the ball: the ball
          // gone from where the case found it (and not at the passer) shows the first pass too.
          const bool moved = s.receives_done == 0 &&
                             !Near(p.p_F_ball, play.p_F_ball, ctx.team->pass_seen_m);
          const bool heard = s.passes_heard > s.receives_done;
          if (!heard && !((s.passer_had_ball || moved) && !near)) {
            step.command = AwaitPass(play, me, actions, s.action, p, tol, dt);
            return step;
          }
        }
        if (OpponentHasBall(p, ctx)) step.abort = AbortReason::kBallLost;
        step.command = GetBall();
        return step;
      }
      case ActionType::kKick:
      case ActionType::kPass: {
        if (s.kicking) {
          // The kick is over once the robot is free again (it no longer holds the ball).
          if (a.type == ActionType::kPass) step.passed_to = play.RobotOfId(a.teammate);
          ++s.kicks_done;
          Advance(s);
          if (step.passed_to >= 0) {
            step.command = Stand();
            return step;  // the pass message goes out this step; the next action waits a step
          }
          continue;
        }
        if (!p.holding_ball) {
          if (OpponentHasBall(p, ctx)) step.abort = AbortReason::kBallLost;
          step.command = GetBall();
          return step;
        }
        const int kick_index = ctx.kicks->Find(a.kick).value_or(0);
        ActionStep aim = AimAndKick(play.KickTrajectory(me, s.kicks_done), kick_index, s, p, ctx);
        return aim;
      }
      case ActionType::kGoTo: {
        const Vec2 target = a.target_F ? play.Adapt(*a.target_F) : p.pose.p_F;
        if (Near(p.pose.p_F, target, tol)) {
          Advance(s);
          continue;
        }
        step.command = WalkTowards(p.pose, target, face_ball, dt);
        return step;
      }
      case ActionType::kTurn: {
        double heading = a.heading_rad.value_or(p.pose.theta_rad);
        if (a.target_F) {
          const Vec2 t = play.Adapt(*a.target_F);
          heading = HeadingTowards(p.pose.p_F, t);
        }
        if (std::abs(WrapAngle(heading - p.pose.theta_rad)) <= ctx.aim_tolerance_rad) {
          Advance(s);
          continue;
        }
        step.command = TurnTowards(p.pose, heading, dt);
        return step;
      }
      case ActionType::kDribble: {
        if (!p.holding_ball) {
          if (OpponentHasBall(p, ctx)) step.abort = AbortReason::kBallLost;
          step.command = GetBall();
          return step;
        }
        const Vec2 target = a.target_F ? play.Adapt(*a.target_F) : p.p_F_ball;
        if (Near(p.p_F_ball, target, tol) || TimeToAim(play, me, s, p, ctx) ||
            p.time_s - s.holding_since_s >= ctx.release_after_s) {
          Advance(s);
          continue;
        }
        const Vec2 shift = target - p.p_F_ball;  // the ball sits at the front: move it there
        const double face = HeadingTowards(Vec2::Zero(), shift);
        step.command = WalkTowards(p.pose, p.pose.p_F + shift, face, dt);
        return step;
      }
    }
  }
  step.finished = s.action >= actions.size();
  return step;
}

}  // namespace foresight
