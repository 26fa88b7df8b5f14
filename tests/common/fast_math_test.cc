// The project's own sin, cos and exp against the standard library.
#include "common/fast_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace foresight {
namespace {

// |a - b| in units of the last place of b.
double Ulps(double a, double b) {
  const double ulp = std::nextafter(std::abs(b), INFINITY) - std::abs(b);
  return std::abs(a - b) / ulp;
}

TEST(FastMathTest, SinCosWithinTwoUlpsOnTheAnglesWeUse) {
  double worst = 0.0;
  for (int i = -400000; i <= 400000; ++i) {
    const double x = i * 2.5e-3;  // [-1000, 1000] rad
    double s, c;
    SinCos(x, &s, &c);
    // Near zeros of sin or cos, compare absolutely (relative error is meaningless there).
    if (std::abs(std::sin(x)) > 1e-3) worst = std::max(worst, Ulps(s, std::sin(x)));
    if (std::abs(std::cos(x)) > 1e-3) worst = std::max(worst, Ulps(c, std::cos(x)));
    ASSERT_NEAR(s, std::sin(x), 1e-14);
    ASSERT_NEAR(c, std::cos(x), 1e-14);
  }
  EXPECT_LE(worst, 2.0);
}

TEST(FastMathTest, SinCosExactAtSpecialAngles) {
  double s, c;
  SinCos(0.0, &s, &c);
  EXPECT_EQ(s, 0.0);
  EXPECT_EQ(c, 1.0);
  SinCos(-M_PI, &s, &c);
  EXPECT_NEAR(s, 0.0, 1e-15);
  EXPECT_EQ(c, -1.0);
}

TEST(FastMathTest, ExpWithinTwoUlps) {
  double worst = 0.0;
  for (int i = -70000; i <= 70000; ++i) {
    const double x = i * 1e-2;
    worst = std::max(worst, Ulps(Exp(x), std::exp(x)));
  }
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(Exp(0.0), 1.0);
  EXPECT_EQ(Exp(-1000.0), 0.0);
  EXPECT_EQ(Exp(1000.0), std::numeric_limits<double>::infinity());
}

TEST(FastMathTest, ExpFastWithinThreeUlps) {
  double worst = 0.0;
  for (int i = -70000; i <= 70000; ++i) {
    const double x = i * 1e-2 + 1e-5;
    worst = std::max(worst, Ulps(ExpFast(x), std::exp(x)));
  }
  EXPECT_LE(worst, 3.0);
  EXPECT_EQ(ExpFast(0.0), 1.0);
  EXPECT_EQ(ExpFast(-800.0), 0.0);
}

TEST(FastMathTest, LogWithinTwoUlps) {
  double worst = 0.0;
  for (int i = 1; i <= 200000; ++i) {
    for (double x : {i * 1e-5, i * 0.37, 1.0 / (i * 7.3)}) {
      if (std::abs(std::log(x)) > 1e-3) worst = std::max(worst, Ulps(Log(x), std::log(x)));
      ASSERT_NEAR(Log(x), std::log(x), 1e-15 * std::max(1.0, std::abs(std::log(x))));
    }
  }
  EXPECT_LE(worst, 2.0);
  // The exponent is read from the bits for normal numbers, by frexp for subnormal ones; both
  // sides of the boundary, and the extremes.
  for (double x : {std::numeric_limits<double>::denorm_min(), 1e-310,
                   std::numeric_limits<double>::min() / 2, std::numeric_limits<double>::min(),
                   std::numeric_limits<double>::min() * 3, 1e300,
                   std::numeric_limits<double>::max()}) {
    EXPECT_NEAR(Log(x), std::log(x), 1e-15 * std::abs(std::log(x))) << x;
  }
  EXPECT_EQ(Log(1.0), 0.0);
  EXPECT_EQ(Log(0.0), -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(Log(-1.0)));
}

}  // namespace
}  // namespace foresight
