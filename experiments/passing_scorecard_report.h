// What the reproduction scorecard (experiments/passing_scorecard.h; Ros et al. 2009, sec. 5.2,
// Tables 1-5) writes: JSON (the contract: every cell with the paper's value, ours, our interval
// and whether the paper's value lies inside; the claims' verdicts per scenario and their
// tally), a terminal text and a self-contained HTML page (report/html_report.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "experiments/passing_scorecard.h"

namespace foresight {

nlohmann::ordered_json PassingScorecardJson(const PassingScorecard& card);
std::string PassingScorecardText(const PassingScorecard& card);
std::string PassingScorecardHtml(const PassingScorecard& card);

}  // namespace foresight
