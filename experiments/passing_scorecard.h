// The reproduction scorecard: the paper's Tables 1-5 (Ros et al. 2009, sec. 5.2;
// experiments/paper_tables.h) cell by cell beside our run of both teams on one configuration,
// with our intervals at the experiment's confidence and whether the paper's value lies inside,
// and the tally of the paper's claims for CBR against the reactive team per scenario.
//
// Our intervals: shares are Wilson intervals, means t intervals (experiments/passing_stats.h);
// sds and shares of a team's total (backing-ups of A and B, individual and cooperative cases)
// have none, so they are shown but not judged. A claim compares the sum of its terms per trial
// (e.g. 2D: the midfield defender's plus the defender's touches) as the paired difference CBR -
// reactive over the trials both teams played from the same random numbers (common random
// numbers, experiments/passing.h); terms "without timeouts" pair only the trials in which neither
// team timed out. It "holds" when the interval excludes 0 on the side of the paper's own CBR -
// reactive difference in that scenario, is "opposite" when it excludes 0 on the other side, and
// otherwise shows "no clear difference".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "experiments/cbr_play.h"
#include "experiments/paper_tables.h"
#include "experiments/passing_causes.h"
#include "experiments/passing_report.h"
#include "experiments/scorecard_table.h"
#include "experiments/world_check.h"

namespace foresight {

enum class ClaimVerdict { kHolds, kOpposite, kNoClearDifference, kNotPlayed };
std::string ClaimVerdictName(ClaimVerdict verdict);  // "holds", "opposite", ...

struct ClaimScenario {
  int scenario = 0;
  double paper_cbr = 0.0;
  double paper_reactive = 0.0;
  int paper_direction = 0;  // sign of paper_cbr - paper_reactive
  MeanStat difference;      // ours, cbr - reactive, paired
  ClaimVerdict verdict = ClaimVerdict::kNotPlayed;
};

struct ClaimTally {
  std::string name;
  std::string statement;
  std::string compared;  // the terms, e.g. "touches_without_timeouts MD + touches_without_timeouts D"
  bool without_timeouts = false;
  std::vector<ClaimScenario> scenarios;
  int holds = 0;
  int opposite = 0;
  int unclear = 0;
};

// What the world did to one team in one scenario (scenario 0: all pooled), beside its tables:
// whether the attackers earned their "to goal" balls, how the goalie fared against their shots on
// target, where the defenders' long kicks went and how many trials the safety cap ended.
struct ScorecardWorldRow {
  std::string team;
  int to_goal = 0;  // goal, close and penalty area
  ScenarioCauses causes;
};

struct PassingScorecard {
  std::string config;  // MatchConfig::name
  std::string paper_file;  // as displayed
  std::string article;
  std::string kicks;     // the run's kick model file, as its provenance shows it
  std::string executor;  // "coarse" or "physics"
  std::string version;
  std::uint64_t seed = 0;
  double confidence = 0.0;
  int trials = 0;  // per scenario and team
  std::vector<ScorecardTable> tables;
  std::vector<ClaimTally> claims;
  double kick_moved_min_m = 0.0;  // the opponents' kicks counted moved at least this far
  bool has_goalie = false;        // the opponents have a goalie (saves mean something)
  std::vector<ScorecardWorldRow> world;  // per team: its scenarios, then all of them pooled
  std::string goalie;        // the goalie model that played (GoalieModelName), or "none"
  WorldCheck world_check;    // the paper's reactive rows beside ours (experiments/world_check.h)
  std::vector<CbrPlayRow> cbr_play;  // how the CBR team played (experiments/cbr_play.h)
};

// `cbr` and `reactive`: the two teams' runs of the same setup and seed (summaries filled).
PassingScorecard BuildPassingScorecard(const PaperTables& paper, const std::string& paper_file,
                                       const PassingRun& cbr, const PassingRun& reactive);

// The claim's verdict from the paper's direction and our paired difference (n >= 2 to judge).
ClaimVerdict JudgeClaim(int paper_direction, const MeanStat& difference);

}  // namespace foresight
