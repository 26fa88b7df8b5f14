// How the CBR team played (experiments/cbr_play.h), from summaries with known counters: totals
// from the per-trial means, the default behaviour's share of robot time, the completion share
// with its Wilson interval, the JSON's keys; a team without the CBR counters gives no rows.
#include "experiments/cbr_play.h"

#include <gtest/gtest.h>

namespace foresight {
namespace {

MeanStat PerTrial(double mean, int n) {
  MeanStat m;
  m.n = n;
  m.mean = mean;
  return m;
}

ScenarioSummary Summary(int trials) {
  ScenarioSummary s;
  s.scenario = 3;
  s.trials = trials;
  s.team_counters = {{"cases_retrieved", PerTrial(4.0, trials)},
                     {"cases_completed", PerTrial(1.5, trials)},
                     {"cases_multi_kick", PerTrial(2.0, trials)},
                     {"cases_multi_kick_completed", PerTrial(0.5, trials)},
                     {"wait_end_timeouts", PerTrial(0.0, trials)},
                     {"no_case", PerTrial(3.0, trials)},
                     {"no_case_path_blocked", PerTrial(2.5, trials)},
                     {"aborts_ball_lost", PerTrial(1.25, trials)},
                     {"robot_time_idle_s", PerTrial(6.0, trials)},
                     {"robot_time_idle_ball_rolling_s", PerTrial(2.0, trials)},
                     {"robot_time_idle_opponent_on_ball_s", PerTrial(1.0, trials)},
                     {"robot_time_await_case_s", PerTrial(1.0, trials)},
                     {"robot_time_adapt_s", PerTrial(5.0, trials)},
                     {"robot_time_execute_s", PerTrial(6.0, trials)},
                     {"robot_time_wait_end_s", PerTrial(2.0, trials)}};
  return s;
}

TEST(CbrPlayTest, TotalsSharesAndTheCompletionInterval) {
  PassingSetup setup;
  setup.params.confidence = 0.95;
  PassingRun run;
  run.setup = &setup;
  run.summaries = {Summary(200)};
  const std::vector<CbrPlayRow> rows = BuildCbrPlay(run);
  ASSERT_EQ(rows.size(), 1u);
  const CbrPlayRow& r = rows[0];
  EXPECT_EQ(r.scenario, 3);
  EXPECT_EQ(r.retrieved, 800);
  EXPECT_EQ(r.completed, 300);
  EXPECT_EQ(r.multi_kick, 400);
  EXPECT_EQ(r.multi_kick_completed, 100);
  EXPECT_DOUBLE_EQ(r.default_share, 7.0 / 20.0);  // idle + await over all five states
  EXPECT_DOUBLE_EQ(r.default_rolling_share, 2.0 / 20.0);
  EXPECT_DOUBLE_EQ(r.default_opponent_share, 1.0 / 20.0);
  const Interval wilson = WilsonInterval(100, 400, 0.95);
  EXPECT_DOUBLE_EQ(r.multi_kick_completed_ci.low, wilson.low);
  EXPECT_DOUBLE_EQ(r.multi_kick_completed_ci.high, wilson.high);
  ASSERT_EQ(r.aborts.size(), 4u);
  int ball_lost = -1;
  for (const auto& [name, count] : r.aborts) {
    if (name == "ball_lost") ball_lost = count;
  }
  EXPECT_EQ(ball_lost, 250);
  const auto json = CbrPlayJson(rows);
  EXPECT_DOUBLE_EQ(json[0]["multi_kick_completed_share"].get<double>(), 0.25);
  EXPECT_EQ(json[0]["no_case_why"]["path_blocked"].get<int>(), 500);
  EXPECT_NE(CbrPlayText(rows).find("multi-kick 100 of 400, 25.0 %"), std::string::npos);
  EXPECT_NE(CbrPlayText(rows).find("default 35.0 % (rolling 10.0, opponent 5.0)"),
            std::string::npos);
}

TEST(CbrPlayTest, ATeamWithoutTheCountersHasNoRows) {
  PassingSetup setup;
  PassingRun run;
  run.setup = &setup;
  ScenarioSummary reactive;
  reactive.trials = 10;
  run.summaries = {reactive};
  EXPECT_TRUE(BuildCbrPlay(run).empty());
  EXPECT_EQ(CbrPlayText({}), "");
}

}  // namespace
}  // namespace foresight
