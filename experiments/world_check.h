// The world check: the paper's rows of one team (the reactive one, WorldCheckSpec in
// models/experiments/ros2009_tables.json) beside ours, scenario by scenario. The reactive team
// is built from the paper's description of it, not from the method under test, so its rows test
// the simulated world: its figures and rules, not the CBR team.
//
// Each of the team's cells of the configuration's tables (Table 1 and 2 for DG, 4 and 5 for 2D)
// gets a verdict: "inside" (the paper's value lies in our interval), "within N points" (a share
// outside the interval whose paper value is at most the spec's within_points from ours), "off",
// or "not judged" (no interval: sds, shares of a team's total). A scenario agrees when every one
// of the spec's measures for the configuration (DG goal, block, out; 2D to goal, out, timeout) is
// inside or within N points; the scenario's line names the measures that are off.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/paper_tables.h"
#include "experiments/scorecard_table.h"

namespace foresight {

struct WorldCheckCell {
  int table = 0;
  std::string column;  // PaperColumn::Label
  bool decides = false;  // one of the spec's measures
  ScorecardCell cell;
  std::string verdict;
};

struct WorldCheckScenario {
  int scenario = 0;
  int trials = 0;
  std::vector<WorldCheckCell> cells;
  bool agrees = false;
  std::vector<std::string> off;  // the deciding measures that are off
};

struct WorldCheck {
  std::string team;
  double within_points = 0.0;
  std::vector<std::string> measures;
  std::vector<WorldCheckScenario> scenarios;
  int agreeing = 0;
};

// From the scorecard's tables (BuildPassingScorecard) and the spec of `paper`.
WorldCheck BuildWorldCheck(const PaperTables& paper, const std::vector<ScorecardTable>& tables,
                           const std::string& config);

nlohmann::ordered_json WorldCheckJson(const WorldCheck& check);
std::string WorldCheckText(const WorldCheck& check);
// The page's rows: one line per scenario, then every cell.
std::vector<std::vector<std::string>> WorldCheckScenarioRows(const WorldCheck& check);
std::vector<std::vector<std::string>> WorldCheckCellRows(const WorldCheck& check);

}  // namespace foresight
