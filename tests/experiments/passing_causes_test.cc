#include "experiments/passing_causes.h"

#include <gtest/gtest.h>

namespace foresight {
namespace {

MatchEvent Event(EventKind kind, Side side, double x_m, double y_m) {
  MatchEvent e;
  e.kind = kind;
  e.side = side;
  e.p_F_ball = Vec2(x_m, y_m);
  return e;
}

// One opponent kick from (x0, y0) that ended at (x1, y1).
void AddOpponentKick(MatchTrialResult& t, double x0, double y0, double x1, double y1) {
  t.events.push_back(Event(EventKind::kKick, Side::kOpponents, x0, y0));
  t.events.push_back(Event(EventKind::kKickEnd, Side::kOpponents, x1, y1));
}

PassingSetup CausesSetup(bool mirrored) {
  PassingSetup setup;
  setup.params.kick_moved_min_m = 0.3;
  setup.mirrored = mirrored;
  return setup;
}

PassingResult OneScenario(std::vector<MatchTrialResult> trials) {
  PassingResult result;
  result.scenarios.push_back({1, "dg_1", std::move(trials)});
  return result;
}

TEST(PassingCausesTest, OpponentKicksCountOnlyLongOnesAndTheOwnGoalSideOfTheAttack) {
  MatchTrialResult t;
  AddOpponentKick(t, 1.0, 0.0, 0.0, 0.0);   // 1 m upfield (away from the goal at +x)
  AddOpponentKick(t, 1.0, 0.0, 1.1, -1.0);  // sideways with +0.1 m towards the goal: counts
  AddOpponentKick(t, 1.0, 0.0, 1.2, 0.0);   // 0.2 m: too short to count
  t.events.push_back(Event(EventKind::kKick, Side::kAttackers, 0.0, 0.0));  // attackers' kick
  t.events.push_back(Event(EventKind::kKickEnd, Side::kAttackers, 2.0, 0.0));
  const std::vector<ScenarioCauses> causes =
      SummariseCauses(OneScenario({t}), CausesSetup(false), 0.95);
  ASSERT_EQ(causes.size(), 1u);
  EXPECT_EQ(causes[0].opponent_kicks_moved, 2);
  EXPECT_EQ(causes[0].opponent_kicks_own_goal, 1);
  const Interval expected = WilsonInterval(1, 2, 0.95);
  EXPECT_DOUBLE_EQ(causes[0].opponent_kicks_own_goal_ci.low, expected.low);
  EXPECT_DOUBLE_EQ(causes[0].opponent_kicks_own_goal_ci.high, expected.high);
}

TEST(PassingCausesTest, TheMirroredGameCountsKicksTowardsMinusX) {
  MatchTrialResult t;
  AddOpponentKick(t, 1.0, 0.0, 0.0, 0.0);  // towards -x: the own goal when mirrored
  const std::vector<ScenarioCauses> causes =
      SummariseCauses(OneScenario({t}), CausesSetup(true), 0.95);
  EXPECT_EQ(causes[0].opponent_kicks_own_goal, 1);
}

TEST(PassingCausesTest, ToGoalByAttackersNeedsAToGoalOutcomeAndAnAttackersKick) {
  MatchTrialResult sent, handed, out;
  sent.outcome = TrialOutcome::kGoal;
  sent.counters.attacker_kick_sent = true;
  handed.outcome = TrialOutcome::kPenaltyArea;  // the last kick was the defenders'
  out.outcome = TrialOutcome::kOut;
  out.counters.attacker_kick_sent = true;
  const std::vector<ScenarioCauses> causes =
      SummariseCauses(OneScenario({sent, handed, out}), CausesSetup(false), 0.95);
  EXPECT_EQ(causes[0].trials, 3);
  EXPECT_EQ(causes[0].to_goal_by_attackers, 1);
}

TEST(PassingCausesTest, PoolingAddsTheCountsAndRecomputesTheIntervals) {
  ScenarioCauses a, b;
  a.trials = 10;
  a.to_goal_by_attackers = 2;
  a.opponent_kicks_moved = 4;
  a.opponent_kicks_own_goal = 1;
  a.shots_on_target = 3;
  a.shots_saved = 1;
  b.trials = 30;
  b.to_goal_by_attackers = 3;
  b.opponent_kicks_moved = 16;
  b.opponent_kicks_own_goal = 0;
  b.safety_cap_ended = 1;
  const ScenarioCauses pooled = PoolCauses({a, b}, 0.95);
  EXPECT_EQ(pooled.scenario, 0);
  EXPECT_EQ(pooled.trials, 40);
  EXPECT_EQ(pooled.to_goal_by_attackers, 5);
  EXPECT_EQ(pooled.opponent_kicks_moved, 20);
  EXPECT_EQ(pooled.opponent_kicks_own_goal, 1);
  EXPECT_EQ(pooled.shots_on_target, 3);
  EXPECT_EQ(pooled.shots_saved, 1);
  EXPECT_EQ(pooled.safety_cap_ended, 1);
  EXPECT_DOUBLE_EQ(pooled.opponent_kicks_own_goal_ci.high, WilsonInterval(1, 20, 0.95).high);
  EXPECT_DOUBLE_EQ(pooled.to_goal_by_attackers_ci.low, WilsonInterval(5, 40, 0.95).low);
}

}  // namespace
}  // namespace foresight
