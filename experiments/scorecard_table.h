// One of the paper's tables beside our run, cell by cell (experiments/passing_scorecard.h builds
// them): the paper's value, ours with its interval at the experiment's confidence, and whether the
// paper's value lies inside.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stats/statistics.h"

namespace foresight {

struct ScorecardCell {
  double paper = 0.0;
  std::optional<double> ours;   // none when we did not play the row's scenario
  std::optional<Interval> ci;   // none for sds and shares of a team's total
  std::optional<bool> inside;   // the paper's value within ci
};

struct ScorecardRow {
  int scenario = 0;
  std::string team;
  int trials = 0;  // our trials behind the row (0: not played)
  std::vector<ScorecardCell> cells;
};

struct ScorecardTable {
  int table = 0;
  std::string source;
  std::string caption;
  std::vector<std::string> columns;  // PaperColumn::Label
  std::vector<ScorecardRow> rows;
  int judged = 0;  // cells with an interval
  int inside = 0;  // of those, the paper's value inside ours
};

}  // namespace foresight
