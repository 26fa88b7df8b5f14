// The stability experiment (experiments/stability.h) on small grids with fixed seeds.
#include "experiments/stability.h"

#include <gtest/gtest.h>

#include "tests/support/test_situations.h"

namespace foresight {
namespace {

StabilityParams SmallParams(Situation situation) {
  StabilityParams p;
  p.situation = std::move(situation);
  p.strategy = Strategy::kNaoth;
  p.grid_step_m = 1.5;             // 6 x 4 positions
  p.heading_step_rad = kPi / 2.0;  // 4 headings
  p.repeats = 20;
  p.sample_counts = {1, 4, 30};
  p.map_samples = 30;
  p.rotation_bin_rad = 10.0 * kDegToRad;
  p.Validate();
  return p;
}

TEST(StabilityTest, GridTilesTheFieldWithCellCentres) {
  const Situation s = testing::MakeSituation({});
  const StabilityGrid grid = MakeStabilityGrid(s.field, 0.30, 5.0 * kDegToRad);
  ASSERT_EQ(grid.positions_F.size(), 30u * 20u);
  EXPECT_EQ(grid.headings_rad.size(), 72u);
  EXPECT_EQ(grid.PoseCount(), 600 * 72);
  EXPECT_NEAR(grid.positions_F.front().x(), -4.35, 1e-12);
  EXPECT_NEAR(grid.positions_F.front().y(), -2.85, 1e-12);
  EXPECT_NEAR(grid.positions_F.back().x(), 4.35, 1e-12);
  EXPECT_NEAR(grid.positions_F.back().y(), 2.85, 1e-12);
  const Pose2 last = grid.PoseAt(grid.PoseCount() - 1);
  EXPECT_NEAR(last.theta_rad, -5.0 * kDegToRad, 1e-12);  // 355 deg, wrapped
  // A step that does not divide the field: whole cells, centred.
  const StabilityGrid odd = MakeStabilityGrid(s.field, 0.7, kPi);
  EXPECT_EQ(odd.positions_F.size(), 12u * 8u);
  EXPECT_NEAR(odd.positions_F.front().x() + odd.positions_F.back().x(), 0.0, 1e-12);
}

TEST(StabilityTest, DecisionKeysSeparateKicksAndRotationBins) {
  const double bin = 10.0 * kDegToRad;
  EXPECT_EQ(DecisionKey(0, 4.0 * kDegToRad, bin), DecisionKey(0, -4.0 * kDegToRad, bin));
  EXPECT_NE(DecisionKey(0, 4.0 * kDegToRad, bin), DecisionKey(0, 6.0 * kDegToRad, bin));
  EXPECT_NE(DecisionKey(0, 0.0, bin), DecisionKey(1, 0.0, bin));
  EXPECT_NE(DecisionKey(-1, 0.0, bin), DecisionKey(0, 0.0, bin));
  EXPECT_EQ(DecisionKey(2, 2.0 * kPi + 0.01, bin), DecisionKey(2, 0.01, bin));
  // +179.9 and -179.9 deg are nearly the same turn: one bin, the one of 180 deg.
  EXPECT_EQ(DecisionKey(0, 179.9 * kDegToRad, bin), DecisionKey(0, -179.9 * kDegToRad, bin));
  EXPECT_NE(DecisionKey(0, 174.0 * kDegToRad, bin), DecisionKey(0, -174.0 * kDegToRad, bin));
}

// Without any noise every decision of a pose is the same: every top share is exactly 1.
TEST(StabilityTest, NoiselessDecisionsAreCompletelyStable) {
  const StabilityResult r = RunStability(SmallParams(testing::MakeNoiselessSituation({})), 3, 2);
  for (const StabilityCount& c : r.counts) {
    EXPECT_EQ(c.share_above_80, 1.0);
    EXPECT_EQ(c.share_at_most_20, 0.0);
    EXPECT_EQ(c.mean_distinct, 1.0);
  }
  EXPECT_EQ(r.decisions, 24LL * 4 * 3 * 20);
}

TEST(StabilityTest, MoreSamplesGiveMoreStableDecisions) {
  const StabilityParams p = SmallParams(testing::MakeSituation(testing::Uncertain({})));
  const StabilityResult r = RunStability(p, 11, 2);
  ASSERT_EQ(r.counts.size(), 3u);
  EXPECT_LT(r.counts[0].mean_top_share, r.counts[1].mean_top_share);
  EXPECT_LT(r.counts[1].mean_top_share, r.counts[2].mean_top_share);
  EXPECT_LE(r.counts[0].share_above_80, r.counts[2].share_above_80);
  EXPECT_GT(r.counts[2].share_above_80, 0.5);
  EXPECT_GT(r.counts[0].mean_distinct, r.counts[2].mean_distinct);
  // Shares are consistent with each other.
  for (const StabilityCount& c : r.counts) {
    EXPECT_LE(c.share_above_80, c.share_above_50);
    EXPECT_LE(c.share_above_50 + c.share_at_most_20, 1.0);
  }
}

TEST(StabilityTest, SameSeedSameResultWithOneThreadOrTwo) {
  const StabilityParams p = SmallParams(testing::MakeSituation(testing::Uncertain({})));
  const StabilityResult one = RunStability(p, 5, 1), two = RunStability(p, 5, 2);
  EXPECT_EQ(one.top_count, two.top_count);
  const StabilityResult other = RunStability(p, 6, 2);
  EXPECT_NE(one.top_count, other.top_count);
}

TEST(StabilityTest, PositionMeansAverageTheHeadings) {
  const StabilityParams p = SmallParams(testing::MakeSituation(testing::Uncertain({})));
  const StabilityResult r = RunStability(p, 5, 2);
  const std::vector<double> means = r.PositionMeans(0);
  ASSERT_EQ(means.size(), r.grid.positions_F.size());
  double sum = 0.0;
  for (int h = 0; h < 4; ++h) sum += r.top_count[static_cast<std::size_t>(4 + h)] / 20.0;
  EXPECT_NEAR(means[1], sum / 4.0, 1e-6);
}

}  // namespace
}  // namespace foresight
