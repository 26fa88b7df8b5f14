// The passing experiment's figures (SVG): the outcome shares per scenario with Wilson intervals
// (Tables 1 and 4), the opponents' ball possession and the trial time with t intervals (Tables
// 1 and 5). The example trial's drawing is experiments/passing_example.h.
#pragma once

#include <string>

#include "experiments/passing_report.h"

namespace foresight {

std::string PassingOutcomesSvg(const PassingRun& run);
std::string PassingPossessionSvg(const PassingRun& run);
std::string PassingTimeSvg(const PassingRun& run);

}  // namespace foresight
