// The reproduction scorecard (experiments/passing_scorecard.h): the verdict of a claim from the
// paper's direction and our paired interval; the tally on hand-made trials; and a tiny run of
// both teams carries every cell of the paper's tables for its configuration (Ros et al. 2009,
// Tables 1-3 for DG, 4-5 for 2D).
#include "experiments/passing_scorecard.h"

#include <gtest/gtest.h>

#include "experiments/passing_comparison.h"
#include "experiments/passing_scorecard_report.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

PassingSetup LoadSetup(const std::string& config, int trials, std::vector<int> scenarios) {
  PassingRequest request;
  request.config = config;
  request.team = "both";
  request.trials = trials;
  request.scenarios = std::move(scenarios);
  return LoadPassingSetup(request, testing::ModelsDir());
}

PaperTables Paper() {
  return LoadPaperTables("ros2009_tables", testing::ModelsDir());
}

PassingRun TeamRun(const PassingSetup& setup, const std::string& team, PassingResult result) {
  PassingRun run;
  run.setup = &setup;
  run.team = team;
  run.provenance.SetInput("kicks", "kicks/aibo.json");
  run.provenance.SetInput("executor", "coarse");
  run.summaries = SummarisePassing(result, setup.params.confidence);
  run.result = std::move(result);
  return run;
}

MeanStat Difference(double low, double high, int n = 10) {
  MeanStat m;
  m.n = n;
  m.mean = 0.5 * (low + high);
  m.ci = {low, high};
  return m;
}

TEST(PassingScorecardTest, VerdictFollowsThePapersDirection) {
  EXPECT_EQ(JudgeClaim(+1, Difference(1.0, 3.0)), ClaimVerdict::kHolds);
  EXPECT_EQ(JudgeClaim(-1, Difference(1.0, 3.0)), ClaimVerdict::kOpposite);
  EXPECT_EQ(JudgeClaim(-1, Difference(-3.0, -1.0)), ClaimVerdict::kHolds);
  EXPECT_EQ(JudgeClaim(+1, Difference(-1.0, 2.0)), ClaimVerdict::kNoClearDifference);
  EXPECT_EQ(JudgeClaim(+1, Difference(1.0, 3.0, 1)), ClaimVerdict::kNoClearDifference);
}

MatchTrialResult Trial(TrialOutcome outcome, int touches_d, double time_s) {
  MatchTrialResult t;
  t.outcome = outcome;
  t.counters.opponent_touches = {touches_d, 0};
  t.counters.opponent_kicks = {0, 0};
  t.counters.attacker_backups = {0, 0};
  t.counters.attacker_kicks = {0, 0};
  t.counters.time_s = time_s;
  return t;
}

const ClaimTally& ClaimNamed(const PassingScorecard& card, const std::string& name) {
  for (const ClaimTally& c : card.claims) {
    if (c.name == name) return c;
  }
  ADD_FAILURE() << "no claim " << name;
  return card.claims.front();
}

// DG scenario 1 by hand: CBR scores in 8 of 10 trials where the reactive team's ball goes out
// (more to goal and fewer out: holds), the defender touches the ball equally often in both (no
// clear difference) and CBR's trials are 5 s shorter, where the paper's are longer (opposite).
TEST(PassingScorecardTest, TallyOnHandMadeTrials) {
  const PassingSetup setup = LoadSetup("dg", 10, {1});
  PassingResult cbr = EmptyPassingResult(setup), reactive = EmptyPassingResult(setup);
  for (int i = 0; i < 10; ++i) {
    const double jitter = 0.1 * i;
    cbr.scenarios[0].trials[i] =
        Trial(i < 8 ? TrialOutcome::kGoal : TrialOutcome::kOut, i % 3, 15.0 + jitter);
    reactive.scenarios[0].trials[i] = Trial(TrialOutcome::kOut, i % 3, 20.0 + 2 * jitter);
  }
  const PassingScorecard card = BuildPassingScorecard(Paper(), "experiments/ros2009_tables.json",
                                                      TeamRun(setup, "cbr", cbr),
                                                      TeamRun(setup, "reactive", reactive));
  ASSERT_EQ(card.claims.size(), 4u);
  const ClaimTally& to_goal = ClaimNamed(card, "more_to_goal");
  ASSERT_EQ(to_goal.scenarios.size(), 4u);
  EXPECT_EQ(to_goal.scenarios[0].verdict, ClaimVerdict::kHolds);
  EXPECT_NEAR(to_goal.scenarios[0].difference.mean, 80.0, 1e-9);  // percentage points
  EXPECT_EQ(to_goal.scenarios[1].verdict, ClaimVerdict::kNotPlayed);
  EXPECT_EQ(to_goal.holds, 1);
  EXPECT_EQ(ClaimNamed(card, "fewer_out").scenarios[0].verdict, ClaimVerdict::kHolds);
  const ClaimTally& possessions = ClaimNamed(card, "fewer_defender_possessions");
  EXPECT_EQ(possessions.compared, "touches D");
  EXPECT_EQ(possessions.scenarios[0].verdict, ClaimVerdict::kNoClearDifference);
  EXPECT_EQ(possessions.unclear, 1);
  const ClaimTally& time = ClaimNamed(card, "trial_time");
  EXPECT_EQ(time.scenarios[0].paper_direction, +1);  // Table 1: 24.39 s against 20.38 s
  EXPECT_EQ(time.scenarios[0].verdict, ClaimVerdict::kOpposite);
  EXPECT_EQ(time.opposite, 1);
  EXPECT_EQ(time.holds, 0);
}

// The world rows: per team its scenario, then all pooled; "to goal" counts every goal, "by the
// attackers" only those an attacker's kick sent.
TEST(PassingScorecardTest, WorldRowsSplitToGoalByWhoSentTheBall) {
  const PassingSetup setup = LoadSetup("dg", 4, {1});
  PassingResult cbr = EmptyPassingResult(setup), reactive = EmptyPassingResult(setup);
  for (int i = 0; i < 4; ++i) {
    cbr.scenarios[0].trials[i] = Trial(TrialOutcome::kGoal, 0, 10.0);
    cbr.scenarios[0].trials[i].counters.attacker_kick_sent = i < 3;
    reactive.scenarios[0].trials[i] = Trial(TrialOutcome::kOut, 0, 10.0);
  }
  const PassingScorecard card = BuildPassingScorecard(Paper(), "experiments/ros2009_tables.json",
                                                      TeamRun(setup, "cbr", cbr),
                                                      TeamRun(setup, "reactive", reactive));
  ASSERT_EQ(card.world.size(), 4u);  // cbr s1, cbr all, reactive s1, reactive all
  EXPECT_EQ(card.world[0].team, "cbr");
  EXPECT_EQ(card.world[0].causes.scenario, 1);
  EXPECT_EQ(card.world[0].to_goal, 4);
  EXPECT_EQ(card.world[0].causes.to_goal_by_attackers, 3);
  EXPECT_EQ(card.world[1].causes.scenario, 0);
  EXPECT_EQ(card.world[1].causes.trials, 4);
  EXPECT_EQ(card.world[1].to_goal, 4);
  EXPECT_EQ(card.world[3].team, "reactive");
  EXPECT_EQ(card.world[3].to_goal, 0);
  EXPECT_NE(PassingScorecardText(card).find("all cbr      to goal 4, by the attackers 75.0 %"),
            std::string::npos)
      << PassingScorecardText(card);
  EXPECT_NE(PassingScorecardText(card).find("| saved 0 of 0 |"), std::string::npos);
}

// Every cell of the paper's tables for the configuration, with our value beside it.
void ExpectEveryCell(const PassingScorecard& card, const PaperTables& paper) {
  std::size_t tables = 0;
  for (const PaperTable& t : paper.tables) {
    if (t.config != card.config) continue;
    ASSERT_LT(tables, card.tables.size());
    const ScorecardTable& ours = card.tables[tables++];
    EXPECT_EQ(ours.table, t.table);
    ASSERT_EQ(ours.rows.size(), t.rows.size());
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      ASSERT_EQ(ours.rows[r].cells.size(), t.columns.size());
      for (std::size_t c = 0; c < t.columns.size(); ++c) {
        const ScorecardCell& cell = ours.rows[r].cells[c];
        EXPECT_EQ(cell.paper, t.rows[r].values[c]);
        EXPECT_TRUE(cell.ours.has_value())
            << "table " << t.table << " row " << r << " " << t.columns[c].Label();
        if (t.columns[c].stat != PaperStat::kSd && t.columns[c].measure != "backups" &&
            t.columns[c].measure.rfind("cases_", 0) != 0) {
          EXPECT_TRUE(cell.ci.has_value()) << t.columns[c].Label();
        }
      }
    }
  }
  EXPECT_EQ(tables, card.tables.size());
}

TEST(PassingScorecardTest, TinyRunHasEveryPaperCell) {
  const PaperTables paper = Paper();
  for (const char* config : {"dg", "2d"}) {
    const PassingSetup setup = LoadSetup(config, 8, {});
    const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
    const PassingResult cbr = RunPassing(setup, "cbr", executor, 5, 2);
    const PassingResult reactive = RunPassing(setup, "reactive", executor, 5, 2);
    const PassingScorecard card =
        BuildPassingScorecard(paper, "experiments/ros2009_tables.json", TeamRun(setup, "cbr", cbr),
                              TeamRun(setup, "reactive", reactive));
    EXPECT_EQ(card.kicks, "kicks/aibo.json");
    EXPECT_EQ(card.executor, "coarse");
    EXPECT_EQ(card.tables.size(), std::string(config) == "dg" ? 3u : 2u);
    EXPECT_EQ(card.has_goalie, std::string(config) == "dg");  // 2D: no saves to report
    EXPECT_EQ(PassingScorecardText(card).find("no goalie") != std::string::npos,
              std::string(config) == "2d");
    ExpectEveryCell(card, paper);
    // A claim on one column is the paired comparison's difference, in the paper's units.
    const PassingComparison comparison = ComparePassing(
        "cbr", cbr, "reactive", reactive,
        std::string(config) == "dg" ? std::vector<std::string>{"D", "G"}
                                    : std::vector<std::string>{"MD", "D"},
        setup.params.confidence);
    const ClaimTally& to_goal = ClaimNamed(card, "more_to_goal");
    for (std::size_t s = 0; s < 4; ++s) {
      EXPECT_NE(to_goal.scenarios[s].verdict, ClaimVerdict::kNotPlayed);
      EXPECT_NEAR(to_goal.scenarios[s].difference.mean,
                  100.0 * comparison.scenarios[s].rows[0].difference.mean, 1e-9);
    }
    const std::string html = PassingScorecardHtml(card);
    EXPECT_NE(html.find("Table " + std::to_string(card.tables.back().table)), std::string::npos);
    EXPECT_EQ(PassingScorecardJson(card)["claims"].size(), 4u);
  }
}

}  // namespace
}  // namespace foresight
