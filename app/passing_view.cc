#include "app/passing_view.h"

#include "app/base_flag.h"
#include "app/cli_values.h"
#include "app/passing_physics.h"
#include "experiments/passing.h"
#include "experiments/passing_replay.h"
#include "experiments/passing_view.h"
#include "report/report_format.h"
#include "validation/trial_view.h"

namespace foresight {

namespace {

// Frames per simulated second of the kicks' scenes (as `simulate --view-rate`'s default).
constexpr double kKickViewRateHz = 100.0;

}  // namespace

std::string PassingViewHtml(const PassingRun& run, std::size_t index, const PassingOptions& o,
                            const std::filesystem::path& models) {
  ViewerScene scene = PassingViewerScene(run, index);
  if (!o.physics) return ViewerHtml(scene);
  const PassingSetup& setup = *run.setup;
  const ScenarioTrials& st = run.result.scenarios.at(index);
  PhysicsKickExecutor executor(setup.field, setup.kicks, models, o.physics_file,
                               ParseBaseFlag(o.base));
  executor.Record(kKickViewRateHz);
  // The very trial the run scored, or an error (the replay is checked bit for bit).
  const MatchTrialResult again =
      ReplayExampleTrial(setup, run.team, executor, ParseSeed(o.seed), st);
  // The k-th kick event of the trial is the k-th kick the executor carried out.
  std::vector<const MatchEvent*> kicks;
  for (const MatchEvent& e : again.events) {
    if (e.kind == EventKind::kKick) kicks.push_back(&e);
  }
  const std::vector<TrialResult>& recorded = executor.recorded();
  for (std::size_t k = 0; k < recorded.size(); ++k) {
    std::string label = "kick " + std::to_string(k + 1);
    if (k < kicks.size()) {
      const MatchEvent& e = *kicks[k];
      const std::size_t robot = e.side == Side::kAttackers ? static_cast<std::size_t>(e.robot)
                                                           : 2 + static_cast<std::size_t>(e.robot);
      label += Format(" at %.2f s: %s, %s", e.time_s, RobotName(setup, robot).c_str(),
                      e.detail.c_str());
    }
    scene.trials.push_back(TrialView(recorded[k], label));
  }
  scene.robot = &executor.robot().model;
  scene.title += ", kicks in physics";
  return ViewerHtml(scene);
}

}  // namespace foresight
