// The passing experiment: the same seed gives the same trials with one thread or two; the
// mirrored game (attacking the goal at -x) gives the same outcome shares within their intervals;
// the summary counts what the trials say.
#include "experiments/passing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "common/error.h"
#include "experiments/passing_replay.h"
#include "experiments/passing_report.h"
#include "experiments/passing_stats.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

PassingSetup LoadSetup(const std::string& config, int trials, bool mirrored,
                       std::vector<int> scenarios) {
  PassingRequest request;
  request.config = config;
  request.trials = trials;
  request.mirrored = mirrored;
  request.scenarios = std::move(scenarios);
  return LoadPassingSetup(request, testing::ModelsDir());
}

std::string Csv(const PassingSetup& setup, const PassingResult& result) {
  PassingRun run;
  run.setup = &setup;
  run.result = result;
  return PassingTrialsCsv(run) + PassingEventsCsv(run);
}

TEST(PassingTest, SameBytesWithOneThreadOrTwo) {
  const PassingSetup setup = LoadSetup("2d", 12, false, {3, 4});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  const std::string one = Csv(setup, RunPassing(setup, "reactive", executor, 3, 1));
  const std::string two = Csv(setup, RunPassing(setup, "reactive", executor, 3, 2));
  EXPECT_EQ(one, two);
  EXPECT_NE(one, Csv(setup, RunPassing(setup, "reactive", executor, 4, 2)));
}

TEST(PassingTest, MirroredGameGivesTheSameSharesWithinTheirIntervals) {
  for (const char* config : {"dg", "2d"}) {
    const PassingSetup plain = LoadSetup(config, 150, false, {});
    const PassingSetup mirror = LoadSetup(config, 150, true, {});
    const CoarseKickExecutor executor(plain.field, plain.kicks.rolling_deceleration_mps2);
    // 99 % intervals: the loop compares about 50 pairs, and two 95 % intervals of the same share
    // miss each other in about 0.6 % of independent pairs, so one pair in the loop would miss in
    // about a quarter of the seeds (it did at seed 21 once the AIBO's kick model was recalibrated
    // on the motor line: 14 % blocks against 4.7 % mirrored in dg scenario 3, 7.5 % against 7.5 %
    // in 1000 trials each). At 99 % the family misses in about 1 % of seeds.
    constexpr double kConfidence = 0.99;
    const auto a = SummarisePassing(RunPassing(plain, "reactive", executor, 21, 2), kConfidence);
    const auto b = SummarisePassing(RunPassing(mirror, "reactive", executor, 21, 2), kConfidence);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t s = 0; s < a.size(); ++s) {
      for (int k = 0; k < kTrialOutcomeCount; ++k) {
        const auto i = static_cast<std::size_t>(k);
        const double share_b = static_cast<double>(b[s].counts[i]) / b[s].trials;
        const double share_a = static_cast<double>(a[s].counts[i]) / a[s].trials;
        // The two runs are independent samples of the same game: their intervals overlap. (An
        // asymmetry such as a tie-break by the robot's left instead of the field's middle made
        // one scenario 99 % out against 26 % mirrored.)
        const Interval& ia = a[s].shares_ci[i];
        const Interval& ib = b[s].shares_ci[i];
        EXPECT_TRUE(ia.low <= ib.high && ib.low <= ia.high)
            << config << " scenario " << s + 1 << " " << TrialOutcomeName(TrialOutcome(k)) << ": "
            << share_a << " vs mirrored " << share_b;
      }
      const Interval& ta = a[s].time_s.ci;
      const Interval& tb = b[s].time_s.ci;
      EXPECT_TRUE(ta.low <= tb.high && tb.low <= ta.high) << config << " scenario " << s + 1;
    }
  }
}

// Without noise (exact kicks, grabs that never fail, steals that always succeed) a trial and
// its mirror image are the same game to the step: every event at the same time, the ball at
// (-x, y). Scenario 1 lines attacker, ball and opponent up on the middle line; a held ball's
// y of -1e-16 instead of 0 in the mirrored game (from sin(pi)) once made the holder dodge to
// the other side there, and 1000 trials showed 93 % outs mirrored against 87 %
// (issue 12, fifth pass; match/reactive_team.cc, kLevelM).
TEST(PassingTest, ANoiselessTrialAndItsMirrorImagePlayTheSameGame) {
  for (const char* config : {"dg", "2d"}) {
    PassingSetup plain = LoadSetup(config, 1, false, {1});
    PassingSetup mirror = LoadSetup(config, 1, true, {1});
    for (PassingSetup* setup : {&plain, &mirror}) {
      // A robot and its mirror image: the calibrated kicks' small biases (forward -0.2 deg, the
      // head kicks 91.0 / -91.1 deg) rounded to the straight and the square directions, the
      // right head kick the left one's mirror image.
      for (KickSpec& kick : setup->kicks.kicks) {
        kick.sigma_speed_mps = 0.0;
        kick.sigma_direction_rad = 0.0;
        kick.direction_rad = std::round(kick.direction_rad / (0.5 * kPi)) * 0.5 * kPi;
      }
      KickSpec& right = setup->kicks.kicks[*setup->kicks.Find("head_kick_right")];
      right = setup->kicks.kicks[*setup->kicks.Find("head_kick_left")];
      right.name = "head_kick_right";
      right.direction_rad = -right.direction_rad;
      setup->robot.grab_failure_rate = 0.0;
      setup->robot.steal_success_rate = 1.0;
    }
    const CoarseKickExecutor executor(plain.field, plain.kicks.rolling_deceleration_mps2);
    const PassingResult plain_result = RunPassing(plain, "reactive", executor, 5, 1);
    const PassingResult mirror_result = RunPassing(mirror, "reactive", executor, 5, 1);
    const MatchTrialResult& a = plain_result.scenarios[0].trials[0];
    const MatchTrialResult& b = mirror_result.scenarios[0].trials[0];
    ASSERT_EQ(a.events.size(), b.events.size()) << config;
    EXPECT_GT(a.events.size(), 20u) << config;  // a game, not a trial that ended at once
    for (std::size_t i = 0; i < a.events.size(); ++i) {
      const MatchEvent& e = a.events[i];
      const MatchEvent& m = b.events[i];
      ASSERT_EQ(e.kind, m.kind) << config << " event " << i << " at " << e.time_s << " s";
      ASSERT_EQ(e.robot, m.robot) << config << " event " << i;
      ASSERT_NEAR(e.time_s, m.time_s, 1e-9) << config << " event " << i;
      ASSERT_NEAR(e.p_F_ball.x(), -m.p_F_ball.x(), 1e-6) << config << " event " << i;
      ASSERT_NEAR(e.p_F_ball.y(), m.p_F_ball.y(), 1e-6) << config << " event " << i;
    }
    EXPECT_EQ(a.outcome, b.outcome) << config;
  }
}

TEST(PassingTest, SummaryCountsTheTrials) {
  const PassingSetup setup = LoadSetup("dg", 20, false, {4});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  const PassingResult result = RunPassing(setup, "reactive", executor, 1, 2);
  const auto summary = SummarisePassing(result, 0.95);
  ASSERT_EQ(summary.size(), 1u);
  int total = 0, to_goal = 0;
  for (int c : summary[0].counts) total += c;
  for (const MatchTrialResult& t : result.scenarios[0].trials) to_goal += IsToGoal(t.outcome);
  EXPECT_EQ(total, 20);
  EXPECT_EQ(summary[0].to_goal, to_goal);
  EXPECT_EQ(result.scenarios[0].scenario, 4);
  EXPECT_FALSE(result.scenarios[0].trials[0].trace.empty());  // the example trial
  EXPECT_TRUE(result.scenarios[0].trials[1].trace.empty());
}

// The example trial played again for a viewer is checked against the trial the run scored: the
// coarse replay is the same trial bit for bit; a scored trial that differs in one event time by
// a nanosecond (a replay that went its own way) is an error naming where, never a viewer of
// another trial; results without the example trial (a shard that did not play it) are refused.
TEST(PassingTest, AReplayedExampleTrialMustBeTheScoredTrial) {
  const PassingSetup setup = LoadSetup("dg", 2, false, {4});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  PassingResult result = RunPassing(setup, "reactive", executor, 1, 2);
  ScenarioTrials& st = result.scenarios[0];
  const MatchTrialResult again = ReplayExampleTrial(setup, "reactive", executor, 1, st);
  EXPECT_EQ(MatchTrialDifference(again, st.trials[0]), "");
  ASSERT_FALSE(st.trials[0].events.empty());
  st.trials[0].events[0].time_s += 1e-9;
  try {
    ReplayExampleTrial(setup, "reactive", executor, 1, st);
    ADD_FAILURE() << "a replay that differs from the scored trial was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("differs from the scored trial in its events[0]"),
              std::string::npos)
        << e.what();
  }
  st.trials[0].trace.clear();
  EXPECT_THROW(ReplayExampleTrial(setup, "reactive", executor, 1, st), InputError);
}

// The 2D replay's events are JSON strings written by the one JSON writer: a quote, a backslash,
// a control character and "</script>" in an event's text leave the page's script whole and the
// events readable as JSON with the text unchanged.
TEST(PassingTest, TheReplaysEventTextIsEscapedJson) {
  const PassingSetup setup = LoadSetup("dg", 1, false, {4});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  PassingRun run;
  run.setup = &setup;
  run.team = "reactive";
  run.result = RunPassing(setup, "reactive", executor, 1, 1);
  MatchTrialResult& t = run.result.scenarios[0].trials[0];
  ASSERT_FALSE(t.trace.empty());
  const std::string odd = "say \"hi\" \\ back\tslash </script><b>";
  MatchEvent e;
  e.kind = EventKind::kKick;
  e.detail = odd;
  t.events.push_back(e);
  const std::string html = PassingReplayHtml(run, 0);
  EXPECT_EQ(html.find("</script><b>"), std::string::npos);
  const std::string open = "const events = ";
  const std::size_t a = html.find(open);
  ASSERT_NE(a, std::string::npos);
  const std::size_t b = html.find(";\n", a);
  const nlohmann::json events =
      nlohmann::json::parse(html.substr(a + open.size(), b - a - open.size()));
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back()[1].get<std::string>(), "A kick " + odd);
}

}  // namespace
}  // namespace foresight
