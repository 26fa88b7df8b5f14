// The CBR team in the match (issue 15): the same bytes with one thread or two; a pass case
// played end to end (the receiver gets the ball); lost messages do not stall the team; the
// paired comparison pairs trial i with trial i.
#include <gtest/gtest.h>

#include <algorithm>

#include "experiments/passing.h"
#include "experiments/passing_comparison.h"
#include "experiments/passing_report.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

PassingSetup LoadSetup(const std::string& team, int trials, std::vector<int> scenarios) {
  PassingRequest request;
  request.config = "dg";
  request.team = team;
  request.trials = trials;
  request.scenarios = std::move(scenarios);
  return LoadPassingSetup(request, testing::ModelsDir());
}

double CounterOf(const MatchTrialResult& t, const std::string& name) {
  for (const TeamPolicy::Counter& c : t.attacker_counters) {
    if (c.name == name) return c.value;
  }
  ADD_FAILURE() << "no counter " << name;
  return -1.0;
}

TEST(PassingCbrTest, SameBytesWithOneThreadOrTwo) {
  const PassingSetup setup = LoadSetup("cbr", 8, {1, 4});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  PassingRun one, two;
  one.setup = two.setup = &setup;
  one.result = RunPassing(setup, "cbr", executor, 5, 1);
  two.result = RunPassing(setup, "cbr", executor, 5, 2);
  EXPECT_EQ(PassingTrialsCsv(one) + PassingEventsCsv(one),
            PassingTrialsCsv(two) + PassingEventsCsv(two));
  one.summaries = SummarisePassing(one.result, 0.95);
  EXPECT_FALSE(one.summaries[0].team_counters.empty());
}

// Scenario 1 (Fig. 12): A behind the ball, B to its side, the defender ahead. The case base
// answers with a pass; the receiver must get the ball before any opponent touches it in most
// trials (a pass can still go astray: the kick's direction noise).
TEST(PassingCbrTest, APassCaseIsPlayedEndToEndAndTheReceiverGetsTheBall) {
  const PassingSetup setup = LoadSetup("cbr", 30, {1});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  const PassingResult result = RunPassing(setup, "cbr", executor, 11, 2);
  int passes = 0, received = 0;
  for (const MatchTrialResult& t : result.scenarios[0].trials) {
    EXPECT_GE(CounterOf(t, "cases_cooperative"), 1.0);
    const auto kick = std::find_if(t.events.begin(), t.events.end(), [](const MatchEvent& e) {
      return e.kind == EventKind::kKick && e.side == Side::kAttackers;
    });
    if (kick == t.events.end() || kick->robot != 0) continue;
    ++passes;
    const auto next = std::find_if(kick + 1, t.events.end(), [](const MatchEvent& e) {
      return e.kind == EventKind::kTouch || e.kind == EventKind::kGrab ||
             e.kind == EventKind::kEnd;
    });
    received += next != t.events.end() && next->side == Side::kAttackers && next->robot == 1 &&
                next->kind != EventKind::kEnd;
  }
  EXPECT_GE(passes, 27);
  EXPECT_GE(received, 24) << "of " << passes << " passes";
}

TEST(PassingCbrTest, LostMessagesDoNotStallTheTeam) {
  PassingSetup setup = LoadSetup("cbr", 12, {2, 3});
  setup.sim.message_loss_rate = 0.3;
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  const PassingResult result = RunPassing(setup, "cbr", executor, 2, 2);
  for (const ScenarioTrials& st : result.scenarios) {
    for (const MatchTrialResult& t : st.trials) {
      const double robot_time_s = 2.0 * t.counters.time_s;
      const double waiting_s = CounterOf(t, "robot_time_await_case_s");
      // Cycles go on: the coordinator retrieves (a case or none) in every trial.
      EXPECT_GE(CounterOf(t, "cases_retrieved") + CounterOf(t, "no_case"), 1.0)
          << st.name << " " << t.counters.time_s;
      // Waiting for a case that a lost message never brings ends within its timeout: the
      // robots spend most of the game playing, not waiting.
      EXPECT_LT(waiting_s, 0.5 * robot_time_s) << st.name << " " << t.counters.time_s;
    }
  }
}

TEST(PassingCbrTest, ComparisonPairsTrialByTrial) {
  const PassingSetup setup = LoadSetup("both", 10, {3});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  const PassingResult cbr = RunPassing(setup, "cbr", executor, 7, 2);
  const PassingResult reactive = RunPassing(setup, "reactive", executor, 7, 2);
  const PassingComparison c =
      ComparePassing("cbr", cbr, "reactive", reactive, {"D", "G"}, 0.95);
  ASSERT_EQ(c.scenarios.size(), 1u);
  double d_time = 0.0;
  for (std::size_t i = 0; i < 10; ++i) {
    d_time += cbr.scenarios[0].trials[i].counters.time_s -
              reactive.scenarios[0].trials[i].counters.time_s;
  }
  const auto row = std::find_if(c.scenarios[0].rows.begin(), c.scenarios[0].rows.end(),
                                [](const PairedRow& r) { return r.measure == "time_s"; });
  ASSERT_NE(row, c.scenarios[0].rows.end());
  EXPECT_NEAR(row->difference.mean, d_time / 10.0, 1e-9);
  EXPECT_NEAR(row->difference.mean, row->first_mean - row->second_mean, 1e-9);
  EXPECT_LE(row->difference.ci.low, row->difference.mean);
  EXPECT_GE(row->difference.ci.high, row->difference.mean);
}

}  // namespace
}  // namespace foresight
