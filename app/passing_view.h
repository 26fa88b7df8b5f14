// `experiment passing`'s 3D viewers (report/viewer_page.h): per scenario, the example trial's
// match (experiments/passing_view.h); with --physics also each of its kicks as the physics trial
// that carried it out, the robot drawn from its URDF. The kicks are recorded by playing the
// example trial again (ReplayExampleTrial) through a recording PhysicsKickExecutor: the same
// random numbers give the same match and the same kicks, which the replay checks bit for bit
// against the scored trial (an internal error otherwise).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "app/passing_inputs.h"
#include "experiments/passing_report.h"

namespace foresight {

std::string PassingViewHtml(const PassingRun& run, std::size_t index, const PassingOptions& o,
                            const std::filesystem::path& models);

}  // namespace foresight
