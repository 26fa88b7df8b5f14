#include "cbr/kick_race.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/geometry.h"
#include "models/walk_command.h"

namespace foresight {

namespace {

// Distance from p to the segment a-b (a point when they coincide).
double DistanceBetween(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double length = (b - a).norm();
  return length > 0.0 ? DistanceToSegment(p, a, (b - a) / length, length) : (p - a).norm();
}

// The getter's first kick or pass trajectory in the ball path, or nullptr.
const FuzzyTrajectory* FirstKickOf(const CaseBallPath& path, int getter) {
  for (const FuzzyTrajectory& t : path.View()) {
    if (t.kicker == getter) return &t;
  }
  return nullptr;
}

}  // namespace

HoldPlan PlanHold(const Case& c, int teammate, std::size_t from_action,
                  const FuzzyTrajectory& kick_trajectory, double heading_rad, const Vec2& ball_F,
                  const Vec2& shift_F, const KickModel& kicks, const HoldParams& hold) {
  HoldPlan plan;
  double heading = heading_rad;
  const auto turn_to = [&](double to_rad) {
    const double turn = std::abs(WrapAngle(to_rad - heading));
    plan.turns_rad += turn;
    plan.hold_s += turn / hold.dribble_turn_radps;
    heading = to_rad;
  };
  plan.held[plan.points++] = ball_F;
  Vec2 ball = ball_F;
  const auto& actions = c.teammates[static_cast<std::size_t>(teammate)].actions;
  for (std::size_t i = from_action; i < actions.size(); ++i) {
    const CaseAction& a = actions[i];
    if (&a == kick_trajectory.kick) {
      const auto index = kicks.Find(a.kick);
      const double direction = index ? kicks.kicks[static_cast<std::size_t>(*index)].direction_rad : 0.0;
      turn_to(HeadingTowards(kick_trajectory.start_F, kick_trajectory.aim_F) - direction);
      if (plan.points < plan.held.size()) plan.held[plan.points++] = kick_trajectory.start_F;
      plan.judged = true;
      return plan;
    }
    switch (a.type) {
      case ActionType::kGetBall:
        break;
      case ActionType::kTurn:
        if (a.heading_rad) turn_to(*a.heading_rad);
        if (a.target_F) turn_to(HeadingTowards(ball, *a.target_F + shift_F));
        break;
      case ActionType::kDribble:
        if (!a.target_F) break;
        turn_to(HeadingTowards(ball, *a.target_F + shift_F));
        plan.dribble_m += (*a.target_F + shift_F - ball).norm();
        plan.hold_s += (*a.target_F + shift_F - ball).norm() / hold.dribble_speed_mps;
        ball = *a.target_F + shift_F;
        if (plan.points < plan.held.size()) plan.held[plan.points++] = ball;
        break;
      default:
        return plan;  // a walk, a wait or a receive before the kick: not judged here
    }
  }
  return plan;
}

KickRace RunKickRace(const Problem& problem, const Case& c, const Correspondence& match,
                     int getter, const CaseBallPath& path, const KickModel& kicks,
                     const RaceParams& race, const HoldParams& hold) {
  KickRace result;
  if (getter < 0 || getter >= match.count) return result;
  const FuzzyTrajectory* first = FirstKickOf(path, getter);
  if (first == nullptr || first->kick == nullptr) return result;
  // As the team plays it: the getter walks to its adapted position behind the ball (sec. 4.2),
  // then to the ball, and grabs it facing the way it came from there.
  const Pose2& pose = problem.teammates[static_cast<std::size_t>(match.problem_index[getter])].pose;
  const Vec2& adapted = match.adapted_F[static_cast<std::size_t>(getter)];
  const double get_s = (adapted - pose.p_F).norm() / race.speed_mps +
                       TimeToBall(adapted, problem.p_F_ball, race);
  const double heading = (problem.p_F_ball - adapted).norm() > 1e-9
                             ? HeadingTowards(adapted, problem.p_F_ball)
                             : pose.theta_rad;
  const HoldPlan plan = PlanHold(c, getter, 0, *first, heading, problem.p_F_ball,
                                 problem.p_F_ball - c.p_F_ball, kicks, hold);
  if (!plan.judged) return result;
  result.judged = true;
  result.kick_spot_F = first->start_F;
  result.hold_s = std::min(plan.hold_s, hold.hold_limit_s);
  result.kick_s = get_s + hold.grab_s + result.hold_s + hold.launch_s;
  result.opponents_s = std::numeric_limits<double>::infinity();
  for (const Vec2& o : problem.opponents) {
    double d = (o - plan.held[0]).norm();
    for (std::size_t i = 1; i < plan.points; ++i) {
      d = std::min(d, DistanceBetween(o, plan.held[i - 1], plan.held[i]));
    }
    result.opponents_s = std::min(result.opponents_s, std::max(0.0, d - race.reach_m) / race.speed_mps);
  }
  result.won = result.kick_s <= result.opponents_s;
  return result;
}

}  // namespace foresight
