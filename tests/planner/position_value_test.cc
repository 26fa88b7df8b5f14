// The potential field and its mapping to a value in [0, 1] (Mellmann & Schlotter, sec. III-D).
#include "planner/position_value.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/test_situations.h"

namespace foresight {
namespace {

double Gauss(double x, double y, double cx, double cy, double sx, double sy) {
  return std::exp(-((x - cx) * (x - cx) / (2 * sx * sx) + (y - cy) * (y - cy) / (2 * sy * sy)));
}

TEST(PositionValueTest, PotentialIsThePapersFormula) {
  const Situation s = testing::MakeSituation({});
  const PositionValue value(s.evaluation.potential, s.field);
  for (const Vec2& p : {Vec2(0, 0), Vec2(3.1, -1.2), Vec2(-4.4, 2.9), Vec2(4.5, 0)}) {
    const double f = -p.x() / 4.5 - Gauss(p.x(), p.y(), 4.5, 0, 2.25, 1.2) +
                     Gauss(p.x(), p.y(), -4.5, 0, 3.375, 1.2);
    EXPECT_NEAR(value.Potential(p), f, 1e-12);
  }
}

TEST(PositionValueTest, ValueSpansZeroToOneOverTheField) {
  const Situation s = testing::MakeSituation({});
  const PositionValue value(s.evaluation.potential, s.field);
  // The best spot is the opponent goal's centre on the line, the worst the own goal's.
  EXPECT_NEAR(value.Value(Vec2(4.5, 0.0)), 1.0, 1e-9);
  EXPECT_NEAR(value.Value(Vec2(-4.5, 0.0)), 0.0, 1e-9);
  double lo = 1.0, hi = 0.0;
  for (double x = -4.5; x <= 4.5; x += 0.05) {
    for (double y = -3.0; y <= 3.0; y += 0.05) {
      const double v = value.Value(Vec2(x, y));
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, 1.0);
  EXPECT_LT(lo, 1e-3);
  EXPECT_GT(hi, 1.0 - 1e-3);
}

TEST(PositionValueTest, CloserToTheOpponentGoalIsBetter) {
  const Situation s = testing::MakeSituation({});
  const PositionValue value(s.evaluation.potential, s.field);
  EXPECT_GT(value.Value(Vec2(2.0, 0.0)), value.Value(Vec2(0.0, 0.0)));
  EXPECT_GT(value.Value(Vec2(3.5, 0.0)), value.Value(Vec2(3.5, 2.5)));
  EXPECT_GT(value.Value(Vec2(-3.0, 2.5)), value.Value(Vec2(-3.0, 0.0)));  // away from own goal
}

}  // namespace
}  // namespace foresight
