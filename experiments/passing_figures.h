// The passing experiment's figures (SVG): the outcome shares per scenario with Wilson intervals
// (Tables 1 and 4), the opponents' ball possession and the trial time with t intervals (Tables
// 1 and 5), and two teams' outcomes side by side. The example trial's drawing is experiments/passing_example.h.
#pragma once

#include <string>

#include "experiments/passing_report.h"

namespace foresight {

std::string PassingOutcomesSvg(const PassingRun& run);
std::string PassingPossessionSvg(const PassingRun& run);
std::string PassingTimeSvg(const PassingRun& run);
// Two teams side by side (e.g. CBR and reactive from the same trial keys): per scenario each
// team's to goal, out and (with a goalie) block shares with their intervals.
std::string PassingTeamsSvg(const PassingRun& first, const PassingRun& second);

}  // namespace foresight
