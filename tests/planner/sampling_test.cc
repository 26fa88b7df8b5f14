// Drawing samples (eq. 1): the drawn speeds, directions and poses have the model's moments.
#include "planner/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/random.h"
#include "common/same_bits.h"
#include "planner/random_lanes.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

struct Moments {
  double mean = 0, sd = 0;
};
Moments Of(const std::vector<double>& xs) {
  Moments m;
  for (double x : xs) m.mean += x;
  m.mean /= xs.size();
  for (double x : xs) m.sd += (x - m.mean) * (x - m.mean);
  m.sd = std::sqrt(m.sd / (xs.size() - 1));
  return m;
}

TEST(SamplingTest, LaunchSpeedAndDirectionFollowTheKickModel) {
  const Situation s = testing::MakeSituation(testing::Uncertain({.x_m = 1.0, .theta_deg = 20}));
  std::vector<DrawnSample> samples;
  DrawSamples(s.state, 11, 20000, samples);
  std::vector<double> speed, direction, x, theta;
  for (const DrawnSample& d : samples) {
    const ConcreteAction a = MakeAction(s.kicks, 0, 0.0, d);
    speed.push_back(a.launch_speed_mps);
    direction.push_back(a.launch_direction_rad);
    x.push_back(d.state.robot.p_F.x());
    theta.push_back(d.state.robot.theta_rad);
  }
  const KickSpec& forward = s.kicks.kicks[0];
  // Standard errors: sd / sqrt(n) for the mean, sd / sqrt(2n) for the sd; allow 4 of them.
  const double n = 20000;
  EXPECT_NEAR(Of(speed).mean, forward.speed_mps, 4 * 0.15 / std::sqrt(n));
  EXPECT_NEAR(Of(speed).sd, 0.15, 4 * 0.15 / std::sqrt(2 * n));
  EXPECT_NEAR(Of(direction).mean, 0.0, 4 * forward.sigma_direction_rad / std::sqrt(n));
  EXPECT_NEAR(Of(direction).sd, forward.sigma_direction_rad,
              4 * forward.sigma_direction_rad / std::sqrt(2 * n));
  EXPECT_NEAR(Of(x).mean, 1.0, 4 * 0.1 / std::sqrt(n));
  EXPECT_NEAR(Of(x).sd, 0.1, 4 * 0.1 / std::sqrt(2 * n));
  EXPECT_NEAR(Of(theta).sd, 5.0 * kDegToRad, 4 * 5.0 * kDegToRad / std::sqrt(2 * n));
}

TEST(SamplingTest, BallIsPlacedRelativeToTheDrawnRobot) {
  const Situation s =
      testing::MakeSituation({.x_m = 1.0, .y_m = 2.0, .theta_deg = 90, .ball_x_m = 0.2});
  const DrawnSample d = DrawSample(s.state, 3, 0);  // no state noise: exact
  EXPECT_NEAR(d.state.p_F_ball.x(), 1.0, 1e-12);
  EXPECT_NEAR(d.state.p_F_ball.y(), 2.2, 1e-12);
}

// The draws of one sample come in a written order (robot x, y, theta, ball y, ball x, speed,
// direction), whatever the compiler: two draws as arguments of one call would be in an
// unspecified order (GCC and Clang differ).
TEST(SamplingTest, TheDrawsComeInTheirWrittenOrder) {
  StateEstimate e;
  e.p_R_ball = Vec2(0.5, -0.25);
  e.sigma_ball_x_m = 0.1;
  e.sigma_ball_y_m = 0.2;
  const DrawnSample d = DrawSample(e, 7, 3);
  RandomStream rng(StreamKey(7, 3));
  double n[7];
  for (double& v : n) v = rng.NextNormal();
  EXPECT_EQ(d.state.p_F_ball.x(), 0.5 + 0.1 * n[4]);
  EXPECT_EQ(d.state.p_F_ball.y(), -0.25 + 0.2 * n[3]);
  EXPECT_EQ(d.z_speed, n[5]);
  EXPECT_EQ(d.z_direction, n[6]);
}

TEST(SamplingTest, SampleIDependsOnlyOnSeedAndI) {
  const Situation s = testing::MakeSituation(testing::Uncertain({}));
  std::vector<DrawnSample> ten, hundred;
  DrawSamples(s.state, 99, 10, ten);
  DrawSamples(s.state, 99, 100, hundred);
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(ten[i].state.p_F_ball, hundred[i].state.p_F_ball);
    EXPECT_EQ(ten[i].z_speed, hundred[i].z_speed);
  }
  EXPECT_NE(DrawSample(s.state, 100, 0).z_speed, ten[0].z_speed);
}

}  // namespace
}  // namespace foresight

namespace foresight {
namespace {

// The drawing in lanes against DrawSample, sample by sample and bit by bit, over enough samples
// that many lanes have a normal on the ziggurat's slow path (the wedge in lanes, the rare tail by
// the scalar IndexedNormal): both ways of DrawSampleLanes, whichever the build uses, so the default
// (SSE2) build tests the lanes too.
TEST(SamplingTest, DrawingInLanesHasDrawSamplesBits) {
  const Situation s = testing::MakeSituation(testing::Uncertain({.x_m = -2.0, .theta_deg = 170}));
  int slow_lanes = 0, tail_lanes = 0, compared = 0;
  for (auto* draw : {&DrawSampleLanesVector, &DrawSampleLanesScalar, &DrawSampleLanes})
  for (std::uint64_t seed : {3ULL, 1234567ULL}) {
    for (std::uint64_t first = 0; first < 16000; first += kLanes) {
      const SampleLanes lanes = (*draw)(s.state, seed, first);
      LaneMask fast = BroadcastMask(-1);
      for (int k = 1; k <= 7; ++k) NormalFastLanes(StreamBitsLanes(lanes.stream, k), fast);
      for (int l = 0; l < kLanes; ++l) {
        const DrawnSample d = DrawSample(s.state, seed, first + l);
        slow_lanes += fast[l] == 0;
        // A tail normal lies beyond the ziggurat's first edge (the noise draws are normals).
        tail_lanes += std::abs(d.z_speed) > random_detail::kZiggurat.x[1] ||
                      std::abs(d.z_direction) > random_detail::kZiggurat.x[1];
        ++compared;
        ASSERT_EQ(lanes.stream[l], d.stream);
        ASSERT_TRUE(SameBits(lanes.robot_x[l], d.state.robot.p_F.x())) << first + l;
        ASSERT_TRUE(SameBits(lanes.robot_y[l], d.state.robot.p_F.y())) << first + l;
        ASSERT_TRUE(SameBits(lanes.robot_theta_rad[l], d.state.robot.theta_rad)) << first + l;
        ASSERT_TRUE(SameBits(lanes.ball_x[l], d.state.p_F_ball.x())) << first + l;
        ASSERT_TRUE(SameBits(lanes.ball_y[l], d.state.p_F_ball.y())) << first + l;
        ASSERT_TRUE(SameBits(lanes.z_speed[l], d.z_speed)) << first + l;
        ASSERT_TRUE(SameBits(lanes.z_direction[l], d.z_direction)) << first + l;
      }
    }
  }
  EXPECT_GT(slow_lanes, compared / 10);  // about 18 % of samples have a slow-path draw
  EXPECT_GT(tail_lanes, 3 * 10);  // about 1.1 in 1,000 samples has a tail in its two noise draws
  // Groups drawn together (the misses of all finished after all fast paths) as one at a time.
  for (auto* draw : {&DrawSampleGroupsVector, &DrawSampleGroupsScalar, &DrawSampleGroups}) {
    for (std::uint64_t first = 0; first < 8000; first += kDrawGroups * kLanes) {
      SampleLanes groups[kDrawGroups];
      (*draw)(s.state, 17, first, kDrawGroups, groups);
      for (int g = 0; g < kDrawGroups; ++g) {
        const SampleLanes one = DrawSampleLanesScalar(s.state, 17, first + g * kLanes);
        for (int l = 0; l < kLanes; ++l) {
          ASSERT_EQ(groups[g].stream[l], one.stream[l]);
          ASSERT_TRUE(SameBits(groups[g].ball_x[l], one.ball_x[l])) << first + g * kLanes + l;
          ASSERT_TRUE(SameBits(groups[g].ball_y[l], one.ball_y[l])) << first + g * kLanes + l;
          ASSERT_TRUE(SameBits(groups[g].robot_theta_rad[l], one.robot_theta_rad[l]));
          ASSERT_TRUE(SameBits(groups[g].z_speed[l], one.z_speed[l])) << first + g * kLanes + l;
          ASSERT_TRUE(SameBits(groups[g].z_direction[l], one.z_direction[l]));
        }
      }
    }
  }
  // DrawSamples uses the lanes and stops at any count.
  std::vector<DrawnSample> some;
  DrawSamples(s.state, 5, 13, some);
  ASSERT_EQ(some.size(), 13u);
  for (int i = 0; i < 13; ++i) {
    const DrawnSample d = DrawSample(s.state, 5, i);
    EXPECT_EQ(some[i].stream, d.stream);
    EXPECT_TRUE(SameBits(some[i].state.p_F_ball.x(), d.state.p_F_ball.x())) << i;
    EXPECT_TRUE(SameBits(some[i].z_direction, d.z_direction)) << i;
  }
}

}  // namespace
}  // namespace foresight
