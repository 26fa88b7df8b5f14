// Decisions on hand-made situations whose right answer is known, and the strategies'
// invariants over many random situations.
#include "planner/decision.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/random.h"
#include "planner/coarse_planner.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

constexpr int kForward = 0, kLeft = 1, kRight = 2;

Decision DecideOn(const Situation& s, Strategy strategy, std::uint64_t seed = 1) {
  return CoarsePlanner(s).Decide(strategy, 30, seed);
}

const ActionEvaluation& Chosen(const Decision& d) {
  return d.kicks[static_cast<std::size_t>(d.kick_index)].choice.evaluation;
}

TEST(DecisionTest, OpenGoalStraightAheadTakesTheForwardKick) {
  const Situation s = testing::MakeSituation(testing::Uncertain({.x_m = 2.8, .y_m = 0.1}));
  for (Strategy strategy : AllStrategies()) {
    const Decision d = DecideOn(s, strategy);
    EXPECT_EQ(d.kick_index, kForward) << StrategyName(strategy);
    EXPECT_LT(std::abs(d.rotation_rad), 5.0 * kDegToRad) << StrategyName(strategy);
    EXPECT_GT(Chosen(d).p_opp_goal, 0.5) << StrategyName(strategy);
  }
}

TEST(DecisionTest, NextToTheSideLineTheKickTowardsTheLineIsRejected) {
  // Facing the opponent goal on the left side line: the left side kick goes out.
  const Situation s = testing::MakeSituation(testing::Uncertain({.x_m = 0.5, .y_m = 2.75}));
  const CoarsePlanner planner(s);
  CoarseActionEvaluator evaluator = planner.MakeEvaluator(30, 1);
  EXPECT_TRUE(evaluator.Evaluate(kLeft, 0.0).too_risky);
  for (Strategy strategy : AllStrategies()) {
    const Decision d = DecideOn(s, strategy);
    ASSERT_GE(d.kick_index, 0);
    const double heading = s.state.robot.theta_rad + d.rotation_rad +
                           s.kicks.kicks[static_cast<std::size_t>(d.kick_index)].direction_rad;
    EXPECT_LT(std::sin(heading), std::sin(45.0 * kDegToRad)) << StrategyName(strategy);
    EXPECT_LE(Chosen(d).p_out, s.evaluation.max_out_share) << StrategyName(strategy);
  }
}

TEST(DecisionTest, FacingTheOwnGoalTheRobotTurnsOrKicksSideways) {
  const Situation s =
      testing::MakeSituation(testing::Uncertain({.x_m = -3.3, .y_m = 0.2, .theta_deg = 180}));
  const CoarsePlanner planner(s);
  CoarseActionEvaluator evaluator = planner.MakeEvaluator(30, 1);
  EXPECT_GT(evaluator.Evaluate(kForward, 0.0).p_own_goal, 0.3);  // the trap is real
  for (Strategy strategy : AllStrategies()) {
    const Decision d = DecideOn(s, strategy);
    if (d.kick_index >= 0) {
      EXPECT_EQ(Chosen(d).p_own_goal, 0.0) << StrategyName(strategy);
    }
  }
}

TEST(DecisionTest, ObstacleInTheWayIsAvoided) {
  const Situation open = testing::MakeSituation(testing::Uncertain({.x_m = 2.8, .y_m = -0.3}));
  const Situation blocked = testing::MakeSituation(testing::Uncertain({.x_m = 2.8, .y_m = -0.3}),
                                                   {{Vec2(3.6, -0.3), 0.2}});
  const Decision d_open = DecideOn(open, Strategy::kOptimalValue);
  const Decision d_blocked = DecideOn(blocked, Strategy::kOptimalValue);
  EXPECT_LT(Chosen(d_blocked).p_opp_goal, Chosen(d_open).p_opp_goal);
  // Without turning, most forward kicks stop at the obstacle; the decision does better.
  const CoarsePlanner blocked_planner(blocked);
  CoarseActionEvaluator straight = blocked_planner.MakeEvaluator(30, 1);
  EXPECT_GT(Chosen(d_blocked).trimmed_utility, straight.Evaluate(kForward, 0.0).trimmed_utility);
}

TEST(DecisionTest, OptimalOneUsesOnlyTheForwardKick) {
  RandomStream rng(StreamKey(5, 0));
  for (int i = 0; i < 30; ++i) {
    const Situation s = testing::MakeSituation(testing::RandomPose(rng, 4.2, 2.8));
    const Decision d = DecideOn(s, Strategy::kOptimalOne, i);
    EXPECT_EQ(d.kick_index, kForward);
    EXPECT_TRUE(d.kicks[kForward].considered);
    EXPECT_FALSE(d.kicks[kLeft].considered);
    EXPECT_FALSE(d.kicks[kRight].considered);
  }
}

// Invariants over random situations: fast never turns more than optimal_value; the optimal
// strategies never pick a kick with an own-goal sample or too many outs unless they say they
// fell back; optimal_all never turns more than optimal_value.
TEST(DecisionTest, StrategyInvariantsOnRandomSituations) {
  RandomStream rng(StreamKey(77, 0));
  int turned = 0;
  for (int i = 0; i < 60; ++i) {
    const Situation s = testing::MakeSituation(testing::RandomPose(rng, 4.3, 2.9));
    const Decision fast = DecideOn(s, Strategy::kFast, i);
    const Decision value = DecideOn(s, Strategy::kOptimalValue, i);
    const Decision all = DecideOn(s, Strategy::kOptimalAll, i);
    EXPECT_LE(std::abs(fast.rotation_rad), std::abs(value.rotation_rad) + 1e-9) << i;
    EXPECT_LE(std::abs(all.rotation_rad), std::abs(value.rotation_rad) + 1e-9) << i;
    turned += std::abs(fast.rotation_rad) > 0.0;
    for (const Decision* d : {&fast, &value, &all}) {
      ASSERT_GE(d->kick_index, 0);
      if (!d->note.empty()) continue;
      EXPECT_EQ(Chosen(*d).p_own_goal, 0.0) << i;
      EXPECT_LE(Chosen(*d).p_out, s.evaluation.max_out_share) << i;
    }
    // optimal_value's choice is the best trimmed utility among the optimised kicks.
    for (const KickOption& k : value.kicks) {
      EXPECT_LE(k.choice.evaluation.trimmed_utility, Chosen(value).trimmed_utility + 1e-12);
    }
  }
  EXPECT_GT(turned, 0);  // the random set does include situations where fast must turn
}

TEST(DecisionTest, SameSeedSameDecision) {
  const Situation s =
      testing::MakeSituation(testing::Uncertain({.x_m = 3.6, .y_m = 1.9, .theta_deg = 10}));
  for (Strategy strategy : AllStrategies()) {
    const Decision a = DecideOn(s, strategy, 42), b = DecideOn(s, strategy, 42);
    EXPECT_EQ(a.kick_index, b.kick_index);
    EXPECT_EQ(a.rotation_rad, b.rotation_rad);  // bitwise
    for (std::size_t k = 0; k < a.kicks.size(); ++k) {
      EXPECT_EQ(a.kicks[k].choice.evaluation.utility, b.kicks[k].choice.evaluation.utility);
    }
  }
}

// One planner deciding for another pose gives the bits of a planner built for that pose: the
// experiments rely on it to decide for thousands of poses without rebuilding the planner.
TEST(DecisionTest, SharedPlannerDecidesForAnyStateLikeAFreshOne) {
  const Situation base = testing::MakeSituation(testing::Uncertain({.x_m = 0.0}));
  const CoarsePlanner shared(base);
  RandomStream rng(StreamKey(5, 0, 0));
  for (int i = 0; i < 6; ++i) {
    const Situation other = testing::MakeSituation(testing::RandomPose(rng, 4.2, 2.8));
    for (Strategy strategy : {Strategy::kFast, Strategy::kOptimalAll, Strategy::kNaoth}) {
      const Decision a = shared.Decide(other.state, strategy, 20, 9);
      const Decision b = CoarsePlanner(other).Decide(strategy, 20, 9);
      EXPECT_EQ(a.kick_index, b.kick_index);
      EXPECT_EQ(a.rotation_rad, b.rotation_rad);  // bitwise
      EXPECT_EQ(a.evaluations, b.evaluations);
    }
  }
}

TEST(DecisionTest, NaothRuleKicksAtOnceWithoutTurning) {
  const Situation s = testing::MakeSituation(testing::Uncertain({.x_m = 2.8}));
  const Decision d = DecideOn(s, Strategy::kNaoth);
  EXPECT_EQ(d.kick_index, kForward);  // >= 30 % goals
  EXPECT_EQ(d.rotation_rad, 0.0);
  EXPECT_EQ(d.evaluations, 4);  // 3 kicks and none, no search
}

}  // namespace
}  // namespace foresight
