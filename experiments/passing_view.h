// The passing experiment's example trials in the 3D viewer (report/viewer_page.h): the match's
// robots as upright bodies of the match's body radius, the ball, the opponents' home regions
// and the attacked penalty area on the carpet, and the event log beside.
#pragma once

#include <cstddef>
#include <string>

#include "experiments/passing_report.h"
#include "report/viewer_page.h"

namespace foresight {

// One traced match trial as a viewer trial (its trace must not be empty).
ViewerTrial MatchViewerTrial(const PassingSetup& setup, const MatchTrialResult& trial,
                             std::string label);

// The viewer scene of the example trial of run.result.scenarios[index] (it must have one): the
// match alone; `experiment passing --physics` adds the trial's kicks (app/passing_view.h).
ViewerScene PassingViewerScene(const PassingRun& run, std::size_t index);

}  // namespace foresight
