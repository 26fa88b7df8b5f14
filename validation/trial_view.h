// Physics trials for the 3D viewer (report/viewer_page.h): a trial's recorded scene with the
// numbers a reader compares trials by (launch, direction, rest, outcome, the drawn causes).
#pragma once

#include <span>
#include <string>

#include "physics/trial.h"
#include "report/viewer_page.h"

namespace foresight {

// The trial's scene (it must have been recorded: TrialResult::scene) and its numbers.
ViewerTrial TrialView(const TrialResult& result, std::string label);

// The numbers shown beside a trial.
ViewerNumbers TrialNumbers(const TrialResult& result);

// Adds every result's trial, labelled "trial i" with i its index in the run.
void AddTrialViews(std::span<const TrialResult> results, ViewerScene& scene);

}  // namespace foresight
