// The strategies experiment in shards (experiments/strategies_shard.h): shards written to JSON
// text, read back and merged give exactly the unsharded runs, the example's steps included.
#include "experiments/strategies_shard.h"

#include <gtest/gtest.h>

#include "experiments/strategy_stats.h"
#include "planner/coarse_simulator.h"
#include "tests/experiments/strategies_test_params.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

void ExpectSameRun(const StrategyRun& a, const StrategyRun& b) {
  EXPECT_EQ(a.end, b.end);
  EXPECT_EQ(a.kicks, b.kicks);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.turn_s, b.turn_s);
  EXPECT_EQ(a.walk_s, b.walk_s);
  EXPECT_EQ(a.around_ball_s, b.around_ball_s);
  EXPECT_EQ(a.last_contact, b.last_contact);
  EXPECT_EQ(a.kick_status.missed, b.kick_status.missed);
  EXPECT_EQ(a.kick_status.not_settled, b.kick_status.not_settled);
  EXPECT_EQ(a.kick_status.fell, b.kick_status.fell);
  EXPECT_EQ(a.kick_status.blocked, b.kick_status.blocked);
  EXPECT_EQ(a.rotations_rad, b.rotations_rad);
  ASSERT_EQ(a.steps_taken.size(), b.steps_taken.size());
  for (std::size_t i = 0; i < a.steps_taken.size(); ++i) {
    const StrategyStep &x = a.steps_taken[i], &y = b.steps_taken[i];
    EXPECT_EQ(x.robot_at_ball.p_F, y.robot_at_ball.p_F);
    EXPECT_EQ(x.robot_at_ball.theta_rad, y.robot_at_ball.theta_rad);
    EXPECT_EQ(x.p_F_ball, y.p_F_ball);
    EXPECT_EQ(x.kick_index, y.kick_index);
    EXPECT_EQ(x.rotation_rad, y.rotation_rad);
    EXPECT_EQ(x.outcome.p_F_rest, y.outcome.p_F_rest);
    EXPECT_EQ(x.outcome.time_s, y.outcome.time_s);
  }
}

// The runs of `count` shards, each written to JSON text and read back, merged.
StrategiesResult MergedShards(const StrategiesParams& params, const OutcomeSimulator* executor,
                              int count) {
  std::vector<ShardPart> parts;
  for (int i = 0; i < count; ++i) {
    const Shard shard{i, count};
    ShardPart part;
    part.header.shard = shard;
    part.results = nlohmann::json::parse(
        StrategiesShardResults(params, RunStrategies(params, executor, 3, 1, {}, shard), shard)
            .dump());
    parts.push_back(part);
  }
  return MergeStrategiesShards(params, 3, parts);
}

TEST(StrategiesShardTest, MergedShardsEqualTheWholeRun) {
  StrategiesParams params = testing::TestStrategiesParams(testing::MakeSituation({}), 23);
  params.example_start = 5;
  const StrategiesResult whole = RunStrategies(params, nullptr, 3, 2);
  ASSERT_FALSE(whole.strategies.front().example.steps_taken.empty());
  const StrategiesResult merged = MergedShards(params, nullptr, 4);
  ASSERT_EQ(merged.strategies.size(), whole.strategies.size());
  for (std::size_t s = 0; s < whole.strategies.size(); ++s) {
    EXPECT_EQ(merged.strategies[s].strategy, whole.strategies[s].strategy);
    for (int start = 0; start < params.starts; ++start) {
      SCOPED_TRACE("strategy " + std::to_string(s) + ", start " + std::to_string(start));
      ExpectSameRun(merged.strategies[s].runs[start], whole.strategies[s].runs[start]);
    }
    ExpectSameRun(merged.strategies[s].example, whole.strategies[s].example);
  }
  EXPECT_EQ(merged.starts.size(), whole.starts.size());
}

// An executor whose robot cannot take its stance for some kicks (a floating base beside a post):
// the ball stays and the status is blocked. Which kicks is fixed by the action's stream, so it
// does not depend on threads or shards.
class SometimesBlocked : public OutcomeSimulator {
 public:
  explicit SometimesBlocked(const Situation& situation) : coarse_(MakeScene(situation)) {}
  Outcome Simulate(const DrawnState& state, const ConcreteAction& action) const override {
    if (action.stream % 3 != 0) return coarse_.Simulate(state, action);
    Outcome blocked;
    blocked.p_F_rest = state.p_F_ball;
    blocked.status = OutcomeStatus::kBlocked;
    return blocked;
  }

 private:
  CoarseSimulator coarse_;
};

// Blocked kicks are counted as blocked, per run and per strategy, never as missed, and survive
// the shard files.
TEST(StrategiesShardTest, BlockedKicksAreCountedAndSurviveTheShards) {
  const StrategiesParams params = testing::TestStrategiesParams(testing::MakeSituation({}), 6);
  const SometimesBlocked executor(params.situation);
  const StrategiesResult whole = RunStrategies(params, &executor, 3, 2);
  const std::vector<StrategySummary> summaries = SummariseStrategies(whole);
  for (std::size_t k = 0; k < summaries.size(); ++k) {
    const StrategySummary& s = summaries[k];
    int kicks = 0, blocked = 0;  // over every run, ended or not
    for (const StrategyRun& run : whole.strategies[k].runs) {
      kicks += run.kicks;
      blocked += run.kick_status.blocked;
    }
    EXPECT_GT(s.kick_status.blocked, 0) << StrategyName(s.strategy);
    EXPECT_EQ(s.kick_status.blocked, blocked) << StrategyName(s.strategy);
    EXPECT_LT(blocked, kicks) << StrategyName(s.strategy);
    EXPECT_EQ(s.kick_status.missed, 0);
    EXPECT_EQ(s.kick_status.fell, 0);
    EXPECT_EQ(s.kick_status.not_settled, 0);
  }
  const StrategiesResult merged = MergedShards(params, &executor, 2);
  for (std::size_t s = 0; s < whole.strategies.size(); ++s) {
    for (int start = 0; start < params.starts; ++start) {
      SCOPED_TRACE("strategy " + std::to_string(s) + ", start " + std::to_string(start));
      ExpectSameRun(merged.strategies[s].runs[start], whole.strategies[s].runs[start]);
    }
  }
}

}  // namespace
}  // namespace foresight
