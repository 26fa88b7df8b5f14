// The carpet's rolling resistance against the analytic roll: d = v^2 / (2 a), on a straight line
// at every heading (the Bullet trap of bullet3 #2117 would bend it off the world axes).
#include <gtest/gtest.h>

#include <cmath>

#include "common/geometry.h"
#include "physics/trial.h"
#include "tests/support/physics_test_scenes.h"

namespace foresight {
namespace {

class FreeRollTest : public ::testing::TestWithParam<std::tuple<double, double>> {};

TEST_P(FreeRollTest, StopsAtTheAnalyticDistanceOnItsLine) {
  const auto [speed_mps, heading_deg] = GetParam();
  const auto data = testing::LoadPhysicsFixture("spl", /*uniform_carpet=*/true);
  const PhysicsScene scene = testing::SceneOf(*data);
  const double r = data->field.ball.radius_m;
  // Start where a 30 m roll stays on the open carpet plane, clear of the goals.
  const Vec2 start(-3.0, -2.5);
  const double heading = heading_deg * kDegToRad;
  const TrialResult result =
      RunRollTrial(scene, RollingBall(start, r, speed_mps, heading), 1, false);
  ASSERT_TRUE(result.settled);
  const double a = data->params.carpet.rolling_deceleration_mps2;
  const double expected_m = speed_mps * speed_mps / (2.0 * a);
  const Vec2 travelled = result.outcome.p_F_rest - start;
  const Vec2 dir(std::cos(heading), std::sin(heading));
  const double along = travelled.dot(dir);
  const double across = std::abs(travelled.x() * dir.y() - travelled.y() * dir.x());
  EXPECT_NEAR(along, expected_m, 0.02 * expected_m);
  EXPECT_LT(across, 0.01);
  // The time to rest is v / a, plus a short tail while the ball's remaining spin winds down
  // against the capped resisting force (about 0.1 s).
  EXPECT_NEAR(result.outcome.time_s, speed_mps / a, 0.01 * speed_mps / a + 0.15);
}

INSTANTIATE_TEST_SUITE_P(SpeedsAndHeadings, FreeRollTest,
                         ::testing::Combine(::testing::Values(1.0, 2.0, 4.0),
                                            ::testing::Values(0.0, 30.0, 45.0, 77.0)));

}  // namespace
}  // namespace foresight
