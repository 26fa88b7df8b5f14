// The kick's mean roll and the roll at z sd (planner/kick_reach.h) against a Monte Carlo of the
// launch speed the coarse model draws, and against the closed form.
#include "planner/kick_reach.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/random.h"

namespace foresight {
namespace {

KickSpec Kick() {
  KickSpec k;
  k.name = "forward";
  k.speed_mps = 1.077;
  k.sigma_speed_mps = 0.1938;
  k.launch_offset_m = 0.05;
  return k;
}

TEST(KickReachTest, ClosedForms) {
  const KickSpec k = Kick();
  const double a = 0.2697;
  EXPECT_DOUBLE_EQ(MeanRollDistance(k, a),
                   0.05 + (1.077 * 1.077 + 0.1938 * 0.1938) / (2.0 * a));
  EXPECT_DOUBLE_EQ(RollDistanceAtSigmas(k, a, 2.0),
                   0.05 + (1.077 + 2 * 0.1938) * (1.077 + 2 * 0.1938) / (2.0 * a));
  EXPECT_DOUBLE_EQ(RollDistanceAtSigmas(k, a, -10.0), 0.05);  // a speed below 0 stays put
}

TEST(KickReachTest, AgreesWithSampledKicks) {
  const KickSpec k = Kick();
  const double a = 0.2697;
  RandomStream rng(StreamKey(7, 0));
  const int n = 200000;
  double sum = 0.0;
  int beyond = 0;
  const double reach = RollDistanceAtSigmas(k, a, 2.0);
  for (int i = 0; i < n; ++i) {
    const double v = k.speed_mps + k.sigma_speed_mps * rng.NextNormal();
    const double d = k.launch_offset_m + StopDistance(std::max(0.0, v), a);
    sum += d;
    beyond += d > reach;
  }
  // Mean: sd of d about 0.8 m, so the standard error is about 0.002 m.
  EXPECT_NEAR(sum / n, MeanRollDistance(k, a), 0.01);
  // 1 - Phi(2) = 0.02275; binomial sd at n = 200000 is 0.00033.
  EXPECT_NEAR(static_cast<double>(beyond) / n, 0.02275, 0.0015);
}

}  // namespace
}  // namespace foresight
