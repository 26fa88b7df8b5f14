#include "cbr/kick_race.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/geometry.h"
#include "models/walk_command.h"

namespace foresight {

namespace {

// Distance from p to the segment a-b.
double DistanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double l2 = d.squaredNorm();
  const double s = l2 > 0.0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (p - (a + s * d)).norm();
}

// The getter's first kick or pass trajectory in the ball path, or nullptr.
const FuzzyTrajectory* FirstKickOf(const CaseBallPath& path, int getter) {
  for (const FuzzyTrajectory& t : path.View()) {
    if (t.kicker == getter) return &t;
  }
  return nullptr;
}

}  // namespace

KickRace RunKickRace(const Problem& problem, const Case& c, const Correspondence& match,
                     int getter, const CaseBallPath& path, const KickModel& kicks,
                     const RaceParams& race, const HoldParams& hold) {
  KickRace result;
  if (getter < 0 || getter >= match.count) return result;
  const FuzzyTrajectory* first = FirstKickOf(path, getter);
  if (first == nullptr || first->kick == nullptr) return result;
  const Pose2& pose = problem.teammates[static_cast<std::size_t>(match.problem_index[getter])].pose;
  const Vec2 shift = problem.p_F_ball - c.p_F_ball;
  const double get_s = TimeToBall(pose.p_F, problem.p_F_ball, race);
  double heading = get_s > 0.0 ? HeadingTowards(pose.p_F, problem.p_F_ball) : pose.theta_rad;
  double hold_s = 0.0;  // from the grab's end (the holding rule's clock)
  const auto turn_to = [&](double to_rad) {
    hold_s += std::abs(WrapAngle(to_rad - heading)) / hold.dribble_turn_radps;
    heading = to_rad;
  };
  // The held path: B, the dribble targets, the kick spot.
  std::array<Vec2, kMaxTrajectories + 2> held;
  std::size_t points = 0;
  held[points++] = problem.p_F_ball;
  Vec2 ball = problem.p_F_ball;
  for (const CaseAction& a : c.teammates[static_cast<std::size_t>(getter)].actions) {
    if (&a == first->kick) break;
    switch (a.type) {
      case ActionType::kGetBall:
        break;
      case ActionType::kTurn:
        if (a.heading_rad) turn_to(*a.heading_rad);
        if (a.target_F) turn_to(HeadingTowards(ball, *a.target_F + shift));
        break;
      case ActionType::kDribble:
        if (!a.target_F) break;
        turn_to(HeadingTowards(ball, *a.target_F + shift));
        hold_s += (*a.target_F + shift - ball).norm() / hold.dribble_speed_mps;
        ball = *a.target_F + shift;
        if (points < held.size()) held[points++] = ball;
        break;
      default:
        return result;  // a walk, a wait or a receive before the kick: not judged here
    }
  }
  const KickSpec& kick =
      kicks.kicks[static_cast<std::size_t>(kicks.Find(first->kick->kick).value_or(0))];
  turn_to(HeadingTowards(first->start_F, first->end_F) - kick.direction_rad);
  result.judged = true;
  result.kick_spot_F = first->start_F;
  if (points < held.size()) held[points++] = first->start_F;
  result.hold_s = std::min(hold_s, hold.hold_limit_s);
  result.kick_s = get_s + hold.grab_s + result.hold_s + hold.launch_s;
  result.opponents_s = std::numeric_limits<double>::infinity();
  for (const Vec2& o : problem.opponents) {
    double d = (o - held[0]).norm();
    for (std::size_t i = 1; i < points; ++i) d = std::min(d, DistanceToSegment(o, held[i - 1], held[i]));
    result.opponents_s = std::min(result.opponents_s, std::max(0.0, d - race.reach_m) / race.speed_mps);
  }
  result.won = result.kick_s <= result.opponents_s;
  return result;
}

}  // namespace foresight
