// A self-contained HTML replay of one trial of the passing experiment: the field with the home
// regions and the attacked penalty area, every robot's and the ball's whole path faintly, and the
// robots and the ball at the time a slider selects (with play/pause and the events up to that
// time listed beside). Everything is inline (SVG, the frames as JSON, a small script for the
// slider): it opens from disk without a network. Besides the 3D viewer pages
// (report/viewer_page.h) it is the only report with a script; a time slider cannot be made
// without one. The same trial in 3D: experiments/passing_view.h.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "experiments/passing_report.h"

namespace foresight {

// The replay of the example trial of run.result.scenarios[index] (the one with a trace).
std::string PassingReplayHtml(const PassingRun& run, std::size_t index);

// The scenario's traced example trial; null when it has none (a shard that did not play it).
const MatchTrialResult* ExampleTrial(const ScenarioTrials& st);
// Robot r of a trial's trace: the attackers "A" and "B", then the opponents by name.
std::string RobotName(const PassingSetup& setup, std::size_t robot);
// The trial's events as the replay lists them (time, "WHO KIND DETAIL"); of the messages only
// the CBR team's decisions.
std::vector<std::pair<double, std::string>> ReplayEvents(const PassingSetup& setup,
                                                         const MatchTrialResult& t);

}  // namespace foresight
