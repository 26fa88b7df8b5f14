// Random problems around a ball for the retrieval tests: 1-4 teammates, one just behind the ball
// and the others within 1.5 m of it, 0-3 opponents within 1.5 m; positions on the Four-Legged
// field. Drawn from a RandomStream, so a fixed seed gives fixed problems.
#pragma once

#include <algorithm>

#include "cbr/problem.h"
#include "common/random.h"

namespace foresight::testing {

inline Problem RandomProblem(RandomStream& rng, DefendingGoal goal, int teammates, int opponents) {
  const auto u = [&](double lo, double hi) { return lo + (hi - lo) * rng.NextUniform(); };
  // x, then y: sequenced (the order of a constructor's arguments is unspecified).
  const auto box = [&](double x_lo, double x_hi, double y_lo, double y_hi) {
    const double x = u(x_lo, x_hi);
    return Vec2(x, u(y_lo, y_hi));
  };
  const auto field = [](const Vec2& p) {
    return Vec2(std::clamp(p.x(), -2.7, 2.7), std::clamp(p.y(), -1.8, 1.8));
  };
  Problem p;
  p.defending = goal;
  p.p_F_ball = box(-2.6, 2.6, -1.7, 1.7);
  const double back = -AttackSign(goal);
  for (int i = 0; i < teammates; ++i) {
    Vec2 d = i == 0 ? box(0.1, 0.5, -0.3, 0.3) : box(-1.5, 1.5, -1.5, 1.5);
    if (i == 0) d.x() *= back;
    const Vec2 at = p.p_F_ball + d;
    p.teammates.push_back({i + 1, Pose2{field(at), u(-3.0, 3.0)}});
  }
  for (int k = 0; k < opponents; ++k) {
    p.opponents.push_back(field(p.p_F_ball + box(-1.5, 1.5, -1.5, 1.5)));
  }
  return p;
}

}  // namespace foresight::testing
