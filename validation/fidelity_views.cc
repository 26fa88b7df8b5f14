#include "validation/fidelity_views.h"

#include <algorithm>
#include <map>

#include "common/error.h"
#include "report/report_format.h"
#include "validation/trial_view.h"

namespace foresight {

namespace {

bool HasKick(const SituationFidelity& s) {
  return s.candidates[s.coarse.choice].kick_index != kNoKick ||
         s.candidates[s.physics_best].kick_index != kNoKick;
}

// The candidates a viewer shows: (role, index into candidates), each kicking one once.
std::vector<std::pair<std::string, int>> ShownCandidates(const SituationFidelity& s) {
  std::vector<std::pair<std::string, int>> shown;
  if (s.candidates[s.coarse.choice].kick_index != kNoKick) {
    shown.emplace_back("coarse choice", s.coarse.choice);
  }
  if (s.physics_best != s.coarse.choice && s.candidates[s.physics_best].kick_index != kNoKick) {
    shown.emplace_back("physics best", s.physics_best);
  }
  return shown;
}

std::string ViewPage(const SituationFidelity& s, int rank, const FidelitySettings& settings,
                     const RobotModel& robot) {
  const Situation& situation = s.situation;
  ViewerScene scene;
  scene.title = Format("Fidelity, worst situation %d shown: %s (%s)", rank + 1,
                       situation.name.c_str(), s.situation_class.c_str());
  scene.about = {{"command", "foresight fidelity"},
                 {"situation", s.file},
                 {"seed", std::to_string(settings.seed)},
                 {"physics trials per candidate", std::to_string(settings.physics_trials)},
                 {"tau-b (coarse)", Fixed(s.coarse.tau_b, 3)},
                 {"regret (coarse)", Fixed(s.coarse.regret, 3)},
                 {"drawn with", ViewerLibraryVersion()}};
  scene.field = &situation.field;
  scene.robot = &robot;
  scene.trials = s.views;
  return ViewerHtml(scene);
}

}  // namespace

std::string FidelityViewFile(int k) { return "worst_" + std::to_string(k + 1) + "_view.html"; }

std::string FidelityActionText(const Situation& situation, int kick, double rotation_rad) {
  return situation.kicks.NameOf(kick) + " " + Fixed(rotation_rad * kRadToDeg, 0) + " deg";
}

std::vector<int> FidelityViewSituations(const std::vector<SituationFidelity>& situations) {
  std::vector<int> shown;
  for (int i : WorstFirst(situations)) {
    if (static_cast<int>(shown.size()) >= kFidelityViewSituations) break;
    if (HasKick(situations[static_cast<std::size_t>(i)])) shown.push_back(i);
  }
  return shown;
}

bool MayBeShown(const std::vector<SituationFidelity>& before, const SituationFidelity& s) {
  if (!HasKick(s)) return false;
  // Situations run before s come first among equals, so each that s is not worse than ranks
  // ahead of it.
  int ahead = 0;
  for (const SituationFidelity& b : before) {
    if (HasKick(b) && !WorseSituation(s, b)) ++ahead;
  }
  return ahead < kFidelityViewSituations;
}

std::vector<ViewerTrial> RecordFidelityViews(const SituationFidelity& s,
                                             PhysicsActionEvaluator& physics) {
  std::vector<ViewerTrial> views;
  for (const auto& [role, index] : ShownCandidates(s)) {
    const CandidateScore& c = s.candidates[static_cast<std::size_t>(index)];
    const std::string action = FidelityActionText(s.situation, c.kick_index, c.rotation_rad);
    const int trials = std::min(kFidelityViewTrials, c.physics.samples);
    for (int i = 0; i < trials; ++i) {
      const TrialResult r = physics.Replay(c.kick_index, c.rotation_rad, i, kFidelityViewRateHz);
      ViewerTrial view = TrialView(r, role + ": " + action + ", trial " + std::to_string(i));
      view.numbers.insert(view.numbers.begin(),
                          {{"candidate", role + ": " + action},
                           {"physics utility", Fixed(c.physics.utility, 3) + " (all trials)"}});
      views.push_back(std::move(view));
    }
  }
  return views;
}

void KeepShownViews(std::vector<SituationFidelity>& situations) {
  const std::vector<int> shown = FidelityViewSituations(situations);
  for (std::size_t i = 0; i < situations.size(); ++i) {
    if (std::find(shown.begin(), shown.end(), static_cast<int>(i)) == shown.end()) {
      situations[i].views.clear();
    }
  }
}

std::vector<std::pair<std::string, std::string>> FidelityViewPages(
    const FidelityResult& result, const FidelitySettings& settings,
    const std::filesystem::path& models) {
  std::vector<std::pair<std::string, std::string>> pages;
  std::map<std::string, Robot> robots;  // drawn from the robot's URDF; no physics
  const std::vector<int> shown = FidelityViewSituations(result.situations);
  for (std::size_t k = 0; k < shown.size(); ++k) {
    const SituationFidelity& s = result.situations[static_cast<std::size_t>(shown[k])];
    if (s.views.empty()) {
      throw InputError(s.file + ": the fidelity results hold no recorded trials for its viewer");
    }
    const std::string& name = s.situation.kicks.robot;
    auto robot = robots.find(name);
    if (robot == robots.end()) robot = robots.emplace(name, LoadRobot(name, models)).first;
    pages.emplace_back(FidelityViewFile(static_cast<int>(k)),
                       ViewPage(s, static_cast<int>(k), settings, robot->second.model));
  }
  return pages;
}

}  // namespace foresight
