// How the CBR team played the method, scenario by scenario, from its own counters
// (cbr/team_counters.h), beside the paper's Table 3: the share of the robots' time in the default
// behaviour (idle and waiting for a case: the paper calls it "not significant", sec. 5.4) and
// how much of it the ball rolled or an opponent had it, how
// many of the cases whose robots kick twice or more between them were played to the end, how the
// others ended (aborts by reason), and why a retrieval found no case.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/passing_report.h"
#include "stats/statistics.h"

namespace foresight {

struct CbrPlayRow {
  int scenario = 0;
  int trials = 0;
  double default_share = 0.0;  // of all robot time: idle and await_case
  // Of all robot time, the idle part while the ball rolled faster than the robots walk and while
  // an opponent touched it (the rest of the default share: no case, races, waiting for a case).
  double default_rolling_share = 0.0;
  double default_opponent_share = 0.0;
  int retrieved = 0;
  int completed = 0;
  int multi_kick = 0;
  int multi_kick_completed = 0;
  Interval multi_kick_completed_ci;  // Wilson, of the share of multi_kick
  int wait_end_timeouts = 0;
  int no_case = 0;
  std::vector<std::pair<std::string, int>> aborts;   // by reason, in AbortReason order
  std::vector<std::pair<std::string, int>> no_case_why;  // path_blocked, too_far, ...
};

// One row per scenario of a CBR team's run (empty for a team without these counters).
std::vector<CbrPlayRow> BuildCbrPlay(const PassingRun& cbr);

nlohmann::ordered_json CbrPlayJson(const std::vector<CbrPlayRow>& rows);
std::string CbrPlayText(const std::vector<CbrPlayRow>& rows);
// The page's rows, one per scenario, with CbrPlayColumns() as their header.
std::vector<std::string> CbrPlayColumns();
std::vector<std::vector<std::string>> CbrPlayRows(const std::vector<CbrPlayRow>& rows);

}  // namespace foresight
