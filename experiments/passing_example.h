// One example trial of the passing experiment drawn like the paper's Fig. 13: the field, the
// opponents' home regions and the attacked penalty area, every robot's path (attackers blue,
// opponents vermilion) and the ball's (black, dashed), the robots where they started (outlined)
// and ended, a numbered mark on every path each step_mark_period_s (the same number on every
// path is the same moment) and a dot where each kick left.
#pragma once

#include <cstddef>
#include <string>

#include "experiments/passing_report.h"

namespace foresight {

// The example trial of run.result.scenarios[index] (the trial with a trace).
std::string PassingExampleSvg(const PassingRun& run, std::size_t index);

}  // namespace foresight
