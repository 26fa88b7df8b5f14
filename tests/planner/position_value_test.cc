// The potential field and its mapping to a value in [0, 1] (Mellmann & Schlotter, sec. III-D).
#include "planner/position_value.h"

#include <gtest/gtest.h>

#include <algorithm>
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

// The extremes the constructor finds (lane-wise grid) against an independent scalar search: the
// same 0.1 m grid scanned point by point, then compass search to 1e-6 m; bit for bit.
double ScalarExtreme(const PositionValue& value, const FieldSpec& field, double sign) {
  const double hx = field.HalfLength(), hy = field.HalfWidth();
  const int nx = static_cast<int>(std::ceil(field.field_length_m / 0.1));
  const int ny = static_cast<int>(std::ceil(field.field_width_m / 0.1));
  Vec2 best(-hx, -hy);
  double best_f = sign * value.Potential(best);
  for (int i = 0; i <= nx; ++i) {
    for (int j = 0; j <= ny; ++j) {
      const Vec2 p(-hx + field.field_length_m * i / nx, -hy + field.field_width_m * j / ny);
      if (sign * value.Potential(p) > best_f) best_f = sign * value.Potential(p), best = p;
    }
  }
  for (double step = 0.1; step > 1e-6; step *= 0.5) {
    for (bool moved = true; moved;) {
      moved = false;
      for (const Vec2& d : {Vec2(step, 0), Vec2(-step, 0), Vec2(0, step), Vec2(0, -step)}) {
        const Vec2 p(std::clamp(best.x() + d.x(), -hx, hx), std::clamp(best.y() + d.y(), -hy, hy));
        if (sign * value.Potential(p) > best_f) best_f = sign * value.Potential(p), best = p, moved = true;
      }
    }
  }
  return sign * best_f;
}

TEST(PositionValueTest, ExtremesAreTheScalarSearchsBitForBit) {
  Situation s = testing::MakeSituation({});
  const PositionValue spl(s.evaluation.potential, s.field);
  EXPECT_EQ(spl.potential_min(), ScalarExtreme(spl, s.field, -1.0));
  EXPECT_EQ(spl.potential_max(), ScalarExtreme(spl, s.field, +1.0));
  // Extremes inside the field, off the grid, in a grid whose size is no multiple of the lanes.
  s.field.field_length_m = 7.37;
  s.field.field_width_m = 5.11;
  s.evaluation.potential.gaussians.push_back({.weight = -2.0, .centre_x_m = 1.234, .centre_y_m = -0.777,
                                              .sigma_x_m = 0.6, .sigma_y_m = 0.4});
  s.evaluation.potential.gaussians.push_back({.weight = 1.5, .centre_x_m = -2.05, .centre_y_m = 1.31,
                                              .sigma_x_m = 0.5, .sigma_y_m = 0.9});
  const PositionValue odd(s.evaluation.potential, s.field);
  EXPECT_EQ(odd.potential_min(), ScalarExtreme(odd, s.field, -1.0));
  EXPECT_EQ(odd.potential_max(), ScalarExtreme(odd, s.field, +1.0));
  EXPECT_GT(odd.Value(Vec2(1.234, -0.777)), 0.99);  // the new basin is the best place
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
