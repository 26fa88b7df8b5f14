// What `foresight experiment passing` writes besides its figures (experiments/passing_figures.h):
// JSON (the contract: inputs, figures and per scenario the rows of the paper's Tables 1, 2, 4, 5
// with intervals), a CSV with one row per trial, a CSV event log (every kick, touch, grab,
// message, backing-up and end, with times) and a terminal text.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/passing_causes.h"
#include "experiments/passing_stats.h"
#include "report/provenance.h"

namespace foresight {

struct PassingRun {
  // Inputs: "file" (the experiment file), "simulation", "field", "kicks", "robot", "config",
  // "team", "executor" ("coarse"), "mirrored".
  RunProvenance provenance;
  const PassingSetup* setup = nullptr;
  std::string team = "reactive";  // the team these trials were played by (one of setup->teams)
  PassingResult result;
  std::vector<ScenarioSummary> summaries;
};

std::string PassingText(const PassingRun& run);

// The attacking team's own counts per trial and scenario, as Ros et al. 2009 count cases in
// Table 3: cases retrieved (individual, cooperative), "no case" (the default behaviour), races
// lost, aborts by reason and the trial's seconds per case retrieved; "" for a team that counts no
// cases (the reactive team).
std::string TeamCountersText(const std::vector<ScenarioSummary>& summaries);
nlohmann::ordered_json PassingJson(const PassingRun& run);
// One scenario's causes (or all scenarios' pooled), as passing.json and the scorecard write them.
nlohmann::ordered_json PassingCausesJson(const ScenarioCauses& causes);
std::string PassingTrialsCsv(const PassingRun& run);
std::string PassingEventsCsv(const PassingRun& run);

}  // namespace foresight
