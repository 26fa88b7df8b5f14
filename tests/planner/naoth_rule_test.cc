// NaoTH's kick rule on hand-made evaluations, and the turn to face the goal.
#include "planner/naoth_rule.h"

#include <gtest/gtest.h>

#include "tests/support/test_situations.h"

namespace foresight {
namespace {

// `potential` at every infield sample's rest position, `goal_potential` at every goal sample's.
ActionEvaluation Counts(int infield, double potential, int goal, int own, int out,
                        double value = 0.5, double goal_potential = 0.0) {
  HypothesisAccumulator h;
  for (int i = 0; i < infield; ++i) h.Add(Category::kInfield, value, potential);
  for (int i = 0; i < goal; ++i) h.Add(Category::kOppGoal, 0, goal_potential);
  for (int i = 0; i < own; ++i) h.Add(Category::kOwnGoal, 0, 0);
  for (int i = 0; i < out; ++i) h.Add(Category::kOut, 0, 0);
  return h.Finish(testing::MakeSituation({}).evaluation);
}

std::vector<KickOption> Kicks(std::vector<ActionEvaluation> evaluations) {
  std::vector<KickOption> kicks;
  for (std::size_t i = 0; i < evaluations.size(); ++i) {
    kicks.push_back({static_cast<int>(i), true, false, {0.0, evaluations[i]}});
  }
  return kicks;
}

const NaothRuleParams kRule{0.85, 0.30};

TEST(NaothRuleTest, MostGoalSamplesWinAboveThePreference) {
  const auto kicks =
      Kicks({Counts(20, -1.0, 10, 0, 0), Counts(18, -1.5, 12, 0, 0), Counts(30, -1.9, 0, 0, 0)});
  EXPECT_EQ(ApplyNaothRule(kRule, kicks, Counts(30, 0.0, 0, 0, 0)).kick_index, 1);
}

// NaoTH breaks a tie on goal samples by the lowest mean potential over all samples, goal samples
// included, not by the utility and not by the infield samples' potential alone.
TEST(NaothRuleTest, ATieOnGoalSamplesGoesToTheLowestPotentialOverAllSamples) {
  // Both kicks: 12 goal samples (40 %), 18 infield. Kick 0 has the higher utility (infield
  // value 0.9 against 0.5) and the lower infield potential (-1.0 against -0.5), but its goal
  // samples rest where the potential is high: over all 30 samples kick 0 averages
  // (18 * -1.0 + 12 * 0.5) / 30 = -0.4 and kick 1 (18 * -0.5 + 12 * -2.0) / 30 = -1.1.
  const ActionEvaluation kick0 = Counts(18, -1.0, 12, 0, 0, 0.9, 0.5);
  const ActionEvaluation kick1 = Counts(18, -0.5, 12, 0, 0, 0.5, -2.0);
  ASSERT_GT(kick0.utility, kick1.utility);
  ASSERT_LT(kick0.potential_avg, kick1.potential_avg);
  const ActionEvaluation none = Counts(30, 0.0, 0, 0, 0);
  EXPECT_EQ(ApplyNaothRule(kRule, Kicks({kick0, kick1}), none).kick_index, 1);
  EXPECT_EQ(ApplyNaothRule(kRule, Kicks({kick1, kick0}), none).kick_index, 0);  // not the order
}

TEST(NaothRuleTest, AnOwnGoalOrTooFewAcceptableSamplesDropAKick) {
  // Kick 0 has 29 goals but one own goal; kick 1 has 26 of 30 acceptable (0.867 > 0.85) and
  // kick 2 only 25 (0.833): kick 2 is dropped although its potential is the lowest.
  const auto kicks =
      Kicks({Counts(0, 0.0, 29, 1, 0), Counts(26, -1.0, 0, 0, 4), Counts(25, -1.8, 0, 0, 5)});
  EXPECT_EQ(ApplyNaothRule(kRule, kicks, Counts(30, 0.0, 0, 0, 0)).kick_index, 1);
}

TEST(NaothRuleTest, NoneWinsWhenNoKickLowersThePotential) {
  const auto kicks = Kicks({Counts(30, 0.4, 0, 0, 0), Counts(30, 0.2, 0, 0, 0)});
  EXPECT_EQ(ApplyNaothRule(kRule, kicks, Counts(30, 0.1, 0, 0, 0)).kick_index, -1);
}

TEST(NaothRuleTest, FaceGoalRotationPointsAtTheGoalCentre) {
  // Robot at the centre spot facing +y, ball at its feet: the goal is 90 deg clockwise.
  const Situation s =
      testing::MakeSituation({.x_m = 0, .y_m = 0, .theta_deg = 90, .ball_x_m = 0.0});
  EXPECT_NEAR(FaceGoalRotation(s), -kPi / 2, 1e-12);
}

}  // namespace
}  // namespace foresight
