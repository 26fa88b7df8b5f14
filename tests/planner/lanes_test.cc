// The SIMD lanes' maths against the project's scalar functions (common/fast_math.h): the same
// operations in the same order, so every lane must have the scalar bits.
#include "planner/lanes.h"

#include <gtest/gtest.h>

#include "common/random.h"

namespace foresight {
namespace {

// Lanes filled from `next`, one value per lane.
template <typename Next>
Lanes Fill(Next&& next) {
  Lanes x{};
  for (int l = 0; l < kLanes; ++l) x[l] = next();
  return x;
}

TEST(LanesTest, SinCosLanesHasTheScalarBits) {
  RandomStream rng(StreamKey(18, 2));
  int compared = 0;
  for (int i = 0; i < 20000; ++i) {
    const double range = i % 2 == 0 ? 4.0 : 40.0;  // every quadrant, and several turns
    const Lanes x = Fill([&] { return range * (2.0 * rng.NextUniform() - 1.0); });
    Lanes s, c;
    SinCosLanes(x, &s, &c);
    for (int l = 0; l < kLanes; ++l) {
      double s_ref, c_ref;
      SinCos(x[l], &s_ref, &c_ref);
      ASSERT_EQ(s[l], s_ref) << x[l];
      ASSERT_EQ(c[l], c_ref) << x[l];
      ++compared;
    }
  }
  EXPECT_EQ(compared, 20000 * kLanes);
}

TEST(LanesTest, ExpFastLanesHasTheScalarBits) {
  RandomStream rng(StreamKey(18, 3));
  for (int i = 0; i < 20000; ++i) {
    const Lanes x = Fill([&] { return -60.0 + 70.0 * rng.NextUniform(); });
    const Lanes e = ExpFastLanes(x);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(e[l], ExpFast(x[l])) << x[l];
  }
  // Beyond +-700 the lanes take the scalar function.
  const Lanes far = Fill([v = -720.0]() mutable { return v += 360.0; });
  const Lanes e = ExpFastLanes(far);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(e[l], ExpFast(far[l])) << far[l];
}

TEST(LanesTest, RoundingTiesGoAwayFromZeroAsTheScalarOne) {
  for (double x : {0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 1e6 + 0.5, -3.0, 0.49999999999999994}) {
    const Lanes rounded = RoundToIntLanes(Broadcast(x));
    EXPECT_EQ(rounded[0], fast_math_detail::RoundToInt(x)) << x;
    EXPECT_EQ(static_cast<std::int64_t>(IntegerBits(rounded)[0]),
              static_cast<std::int64_t>(fast_math_detail::RoundToInt(x)))
        << x;
  }
}

TEST(LanesTest, SelectMinAndClampFollowTheStandardLibrary) {
  const Lanes a = Broadcast(1.0), b = Broadcast(2.0);
  EXPECT_EQ(Min(a, b)[0], 1.0);
  EXPECT_EQ(Min(b, a)[0], 1.0);
  EXPECT_EQ(Clamp(Broadcast(-3.0), Broadcast(0.0), Broadcast(1.0))[0], 0.0);
  EXPECT_EQ(Clamp(Broadcast(3.0), Broadcast(0.0), Broadcast(1.0))[0], 1.0);
  EXPECT_EQ(Abs(Broadcast(-0.25))[0], 0.25);
  EXPECT_TRUE(Any(Broadcast(1.0) > 0.5));
  EXPECT_FALSE(Any(Broadcast(1.0) > 1.5));
}

}  // namespace
}  // namespace foresight
