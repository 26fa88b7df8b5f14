// The strategies experiment (experiments/strategy_run.h, strategies.h, strategy_stats.h): exact
// times on a scripted start, the strategies' invariants over random starts, determinism. The
// physics executor through the same code is tested in tests/app/strategies_physics_test.cc.
#include "experiments/strategies.h"

#include <gtest/gtest.h>

#include "experiments/strategy_stats.h"
#include "planner/coarse_simulator.h"
#include "tests/experiments/strategies_test_params.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

constexpr int kForward = 0;

StrategiesParams Params(Situation situation, int starts) {
  return testing::TestStrategiesParams(std::move(situation), starts);
}

TEST(StrategiesTest, StartsLieOnTheFieldAndRepeat) {
  const Situation s = testing::MakeSituation({});
  for (int i = 0; i < 200; ++i) {
    const StartPosition a = DrawStart(s.field, 4, i), b = DrawStart(s.field, 4, i);
    EXPECT_EQ(a.robot.p_F, b.robot.p_F);
    EXPECT_EQ(a.p_F_ball, b.p_F_ball);
    EXPECT_LE(std::abs(a.p_F_ball.x()), s.field.HalfLength());
    EXPECT_LE(std::abs(a.p_F_ball.y()), s.field.HalfWidth());
    EXPECT_LE(std::abs(a.robot.p_F.y()), s.field.HalfWidth());
  }
  EXPECT_NE(DrawStart(s.field, 4, 0).p_F_ball, DrawStart(s.field, 5, 0).p_F_ball);
}

// Robot at (2.5, 0.3) facing +90 deg, ball at (3.0, 0.3): it turns -90 deg (1.5 s at 60 deg/s),
// walks 0.35 m to where the ball lies 0.15 m ahead (1.75 s at 0.2 m/s) and, without noise,
// scores with the forward kick (2.16 m of roll for 1.5 m to the goal line).
TEST(StrategiesTest, ApproachTimesAreExactOnAScriptedStart) {
  const StrategiesParams p = Params(testing::MakeNoiselessSituation({}), 1);
  const CoarsePlanner planner(p.situation);
  const CoarseSimulator coarse(MakeScene(p.situation));
  const StrategyRunContext context{p, planner, coarse};
  StartPosition start;
  start.robot = {Vec2(2.5, 0.3), kPi / 2.0};
  start.p_F_ball = Vec2(3.0, 0.3);  // straight ahead after a -90 deg turn
  const StrategyRun run = RunStrategy(context, Strategy::kOptimalValue, start, 1, true);
  EXPECT_EQ(run.end, RunEnd::kGoal);
  EXPECT_EQ(run.kicks, 1);
  EXPECT_NEAR(run.turn_s, 1.5, 1e-12);                 // 90 deg at 60 deg/s
  EXPECT_NEAR(run.walk_s, (0.5 - 0.15) / 0.2, 1e-12);  // to the ball's feet
  ASSERT_EQ(run.steps_taken.size(), 1u);
  EXPECT_EQ(run.steps_taken[0].kick_index, kForward);
}

// Without noise the forward kick rolls d = v^2 / 2a along the x axis: from the centre spot the
// ball rests at d and 2 d (4.32 m, short of the goal line) and the third kick scores. After a
// kick the robot stands where it kicked from, 0.15 m behind the ball it kicked, so every later
// approach walks exactly d, straight ahead, without turning.
TEST(StrategiesTest, RobotFollowsTheBallKickByKickWithExactTimes) {
  const StrategiesParams p = Params(testing::MakeNoiselessSituation({}), 1);
  const CoarsePlanner planner(p.situation);
  const CoarseSimulator coarse(MakeScene(p.situation));
  const StrategyRunContext context{p, planner, coarse};
  StartPosition start;
  start.robot = {Vec2(-1.0, 0.0), 0.0};
  start.p_F_ball = Vec2(0.0, 0.0);
  const StrategyRun run = RunStrategy(context, Strategy::kOptimalValue, start, 1, true);
  const double d = 1.08 * 1.08 / (2.0 * p.situation.kicks.rolling_deceleration_mps2);
  ASSERT_EQ(run.end, RunEnd::kGoal);
  ASSERT_EQ(run.kicks, 3);
  for (int k = 0; k < 3; ++k) {
    const StrategyStep& step = run.steps_taken[static_cast<std::size_t>(k)];
    EXPECT_EQ(step.kick_index, kForward);
    EXPECT_EQ(step.rotation_rad, 0.0);
    EXPECT_NEAR(step.p_F_ball.x(), k * d, 1e-9) << k;
    EXPECT_NEAR(step.robot_at_ball.p_F.x(), k * d - 0.15, 1e-9) << k;
    EXPECT_NEAR(step.robot_at_ball.p_F.y(), 0.0, 1e-9) << k;
  }
  EXPECT_EQ(run.turn_s, 0.0);
  EXPECT_EQ(run.around_ball_s, 0.0);
  EXPECT_NEAR(run.walk_s, (0.85 + 2.0 * d) / 0.2, 1e-9);
}

class StrategiesRunTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    params_ = new StrategiesParams(Params(testing::MakeSituation(testing::Uncertain({})), 40));
    coarse_ = new CoarseSimulator(MakeScene(params_->situation));
    result_ = new StrategiesResult(RunStrategies(*params_, nullptr, 21, 2));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete coarse_;
    delete params_;
  }
  static StrategiesParams* params_;
  static CoarseSimulator* coarse_;
  static StrategiesResult* result_;
};
StrategiesParams* StrategiesRunTest::params_ = nullptr;
CoarseSimulator* StrategiesRunTest::coarse_ = nullptr;
StrategiesResult* StrategiesRunTest::result_ = nullptr;

TEST_F(StrategiesRunTest, EveryStrategyPlaysEveryStartToAnEnd) {
  ASSERT_EQ(result_->strategies.size(), 4u);
  for (const StrategyRuns& runs : result_->strategies) {
    ASSERT_EQ(runs.runs.size(), 40u);
    int ended = 0;
    for (const StrategyRun& run : runs.runs) {
      ended += run.end != RunEnd::kStepLimit;
      EXPECT_EQ(run.rotations_rad.size(), static_cast<std::size_t>(run.kicks));
      EXPECT_GT(run.TotalTime(), 0.0);
    }
    EXPECT_GE(ended, 38) << StrategyName(runs.strategy);
    EXPECT_FALSE(runs.example.steps_taken.empty());
  }
}

TEST_F(StrategiesRunTest, OptimalOneKicksOnlyForward) {
  const StrategyRuns& one = result_->strategies[3];
  ASSERT_EQ(one.strategy, Strategy::kOptimalOne);
  for (const StrategyStep& step : one.example.steps_taken) EXPECT_EQ(step.kick_index, kForward);
  // Rerun a few starts with their steps recorded.
  const CoarsePlanner planner(params_->situation);
  const StrategyRunContext context{*params_, planner, *coarse_};
  for (int i = 0; i < 10; ++i) {
    const StrategyRun run =
        RunStrategy(context, Strategy::kOptimalOne, result_->starts[i], RunKey(21, i), true);
    for (const StrategyStep& step : run.steps_taken) EXPECT_EQ(step.kick_index, kForward);
    EXPECT_EQ(run.kicks, one.runs[static_cast<std::size_t>(i)].kicks);  // recording changes nothing
  }
}

TEST_F(StrategiesRunTest, FastTurnsLeastAroundTheBall) {
  const std::vector<StrategySummary> s = SummariseStrategies(*result_);
  ASSERT_EQ(s[0].strategy, Strategy::kFast);
  for (std::size_t i = 1; i < s.size(); ++i) {
    EXPECT_LT(s[0].mean_around_ball_s, s[i].mean_around_ball_s) << StrategyName(s[i].strategy);
    EXPECT_GT(s[0].turns_zero * s[i].kicks_total, s[i].turns_zero * s[0].kicks_total)
        << StrategyName(s[i].strategy) << ": fast kicks without a turn more often";
    EXPECT_TRUE(s[i].paired_with_fast);
  }
  EXPECT_GT(s[0].turns_zero, s[0].kicks_total / 2);  // fast mostly kicks at once
}

TEST_F(StrategiesRunTest, SummaryCountsAddUp) {
  for (const StrategySummary& s : SummariseStrategies(*result_)) {
    EXPECT_EQ(s.goals + s.own_goals + s.outs + s.step_limits, 40);
    double runs = 0.0, turns = 0.0;
    for (double c : s.kick_counts) runs += c;
    for (double c : s.turn_bins) turns += c;
    EXPECT_EQ(runs, s.ended);
    EXPECT_EQ(s.ended + s.step_limits, 40);
    EXPECT_LE(s.step_limits_at_contact, s.step_limits);
    EXPECT_EQ(turns + s.turns_zero, s.kicks_total);
    EXPECT_LE(s.goal_share_95.low, static_cast<double>(s.goals) / 40);
    EXPECT_GE(s.goal_share_95.high, static_cast<double>(s.goals) / 40);
  }
}

TEST_F(StrategiesRunTest, SameSeedSameRunsWithOneThread) {
  const StrategiesResult one =
      RunStrategies(*params_, coarse_, 21, 1);  // the same coarse model, given
  for (std::size_t s = 0; s < one.strategies.size(); ++s) {
    for (std::size_t i = 0; i < one.strategies[s].runs.size(); ++i) {
      const StrategyRun &a = one.strategies[s].runs[i], &b = result_->strategies[s].runs[i];
      EXPECT_EQ(a.kicks, b.kicks);
      EXPECT_EQ(a.TotalTime(), b.TotalTime());  // bitwise
      EXPECT_EQ(a.rotations_rad, b.rotations_rad);
    }
  }
}

}  // namespace
}  // namespace foresight
