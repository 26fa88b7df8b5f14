// NaoTH's kick rule on hand-made evaluations, and the turn to face the goal.
#include "planner/naoth_rule.h"

#include <gtest/gtest.h>

#include "tests/support/test_situations.h"

namespace foresight {
namespace {

ActionEvaluation Counts(int infield, double potential, int goal, int own, int out) {
  HypothesisAccumulator h;
  for (int i = 0; i < infield; ++i) h.Add(Category::kInfield, 0.5, potential);
  for (int i = 0; i < goal; ++i) h.Add(Category::kOppGoal, 0, 0);
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
