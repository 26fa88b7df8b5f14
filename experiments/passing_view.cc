#include "experiments/passing_view.h"

#include <cassert>

#include "experiments/passing_replay.h"
#include "report/report_format.h"

namespace foresight {

namespace {

// The bodies' drawn height, in body radii: drawing only (the match simulator's robots are
// discs; models/match/aibo_ers7.json's 0.12 m radius gives 0.36 m, about an ERS-7 with its
// head up).
constexpr double kBodyHeightPerRadius = 3.0;

}  // namespace

ViewerTrial MatchViewerTrial(const PassingSetup& setup, const MatchTrialResult& trial,
                             std::string label) {
  assert(!trial.trace.empty());
  ViewerTrial view;
  view.label = std::move(label);
  SceneTrace& trace = view.trace;
  trace.rate_hz = 1.0 / setup.params.trace_period_s;
  trace.phases = {"match"};
  const std::size_t robots = trial.trace.front().robots.size();
  for (std::size_t r = 0; r < robots; ++r) {
    const double radius = setup.robot.body_radius_m;
    trace.bodies.push_back(
        {RobotName(setup, r), r < 2 ? 0 : 1, radius, kBodyHeightPerRadius * radius});
  }
  for (const TraceFrame& f : trial.trace) {
    SceneFrame frame;
    frame.t_s = f.time_s;
    frame.ball.p_F = Eigen::Vector3d(f.p_F_ball.x(), f.p_F_ball.y(), setup.field.ball.radius_m);
    frame.bodies = f.robots;
    trace.frames.push_back(std::move(frame));
  }
  view.events = ReplayEvents(setup, trial);
  view.numbers = {{"outcome", std::string(TrialOutcomeName(trial.outcome))},
                  {"duration", Format("%.1f s", trial.trace.back().time_s)},
                  {"events", std::to_string(trial.events.size())}};
  return view;
}

ViewerScene PassingViewerScene(const PassingRun& run, std::size_t index) {
  const PassingSetup& setup = *run.setup;
  const ScenarioTrials& st = run.result.scenarios.at(index);
  const MatchTrialResult* example = ExampleTrial(st);
  assert(example != nullptr);
  ViewerScene scene;
  scene.title = "Passing, scenario " + std::to_string(st.scenario) + " (" + st.name + "), " +
                run.team + " attacking";
  scene.about = {{"command", "foresight experiment passing"},
                 {"team", run.team},
                 {"scenario", st.name},
                 {"seed", std::to_string(run.provenance.seed)},
                 {"version", run.provenance.version},
                 {"drawn with", ViewerLibraryVersion()}};
  scene.field = &setup.field;
  for (const OpponentSpec& o : setup.config.opponents) {
    scene.regions.push_back({o.name + "'s region", o.region, 1});
  }
  scene.regions.push_back(
      {"penalty area", PenaltyArea(setup.field, setup.sim, setup.mirrored ? -1.0 : 1.0), 2});
  scene.trials.push_back(
      MatchViewerTrial(setup, *example, "the match (example trial " +
                                            std::to_string(ExampleTrialIndex(setup)) + ")"));
  return scene;
}

}  // namespace foresight
