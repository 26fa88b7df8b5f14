#include "validation/fidelity_views.h"

#include <algorithm>

#include "physics/physics_setup.h"
#include "planner/sampling.h"
#include "report/report_format.h"
#include "report/viewer_page.h"
#include "validation/trial_view.h"

namespace foresight {

namespace {

bool HasKick(const SituationFidelity& s) {
  return s.candidates[s.coarse.choice].kick_index != kNoKick ||
         s.candidates[s.physics_best].kick_index != kNoKick;
}

std::string ViewPage(const SituationFidelity& s, int rank, const FidelitySettings& settings,
                     const std::filesystem::path& models) {
  auto setup = LoadPhysicsSetup(s.situation, models, settings.physics_file, settings.base);
  const Situation& situation = setup->situation;
  std::vector<DrawnSample> samples;
  DrawSamples(situation.state, settings.seed, settings.physics_trials, samples);
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
  scene.robot = &setup->robot.model;
  const std::vector<std::pair<std::string, int>> candidates = {
      {"coarse choice", s.coarse.choice}, {"physics best", s.physics_best}};
  for (const auto& [role, index] : candidates) {
    if (role == "physics best" && index == s.coarse.choice) continue;  // shown once
    const CandidateScore& c = s.candidates[static_cast<std::size_t>(index)];
    if (c.kick_index == kNoKick) continue;
    const std::string action = FidelityActionText(situation, c.kick_index, c.rotation_rad);
    const int trials = std::min(kFidelityViewTrials, settings.physics_trials);
    for (int i = 0; i < trials; ++i) {
      const DrawnSample& sample = samples[static_cast<std::size_t>(i)];
      const ConcreteAction a = MakeAction(situation.kicks, c.kick_index, c.rotation_rad, sample);
      const TrialResult r = setup->simulator->Run(sample.state, a, false, kFidelityViewRateHz);
      ViewerTrial view = TrialView(r, role + ": " + action + ", trial " + std::to_string(i));
      view.numbers.insert(view.numbers.begin(),
                          {{"candidate", role + ": " + action},
                           {"physics utility", Fixed(c.physics.utility, 3) + " (all trials)"}});
      scene.trials.push_back(std::move(view));
    }
  }
  return ViewerHtml(scene);
}

}  // namespace

std::string FidelityViewFile(int k) { return "worst_" + std::to_string(k + 1) + "_view.html"; }

std::string FidelityActionText(const Situation& situation, int kick, double rotation_rad) {
  return situation.kicks.NameOf(kick) + " " + Fixed(rotation_rad * kRadToDeg, 0) + " deg";
}

std::vector<int> FidelityViewSituations(const FidelityResult& result) {
  std::vector<int> shown;
  for (int i : WorstFirst(result)) {
    if (static_cast<int>(shown.size()) >= kFidelityViewSituations) break;
    if (HasKick(result.situations[static_cast<std::size_t>(i)])) shown.push_back(i);
  }
  return shown;
}

std::vector<std::pair<std::string, std::string>> FidelityViewPages(
    const FidelityResult& result, const FidelitySettings& settings,
    const std::filesystem::path& models) {
  std::vector<std::pair<std::string, std::string>> pages;
  const std::vector<int> shown = FidelityViewSituations(result);
  for (std::size_t k = 0; k < shown.size(); ++k) {
    const SituationFidelity& s = result.situations[static_cast<std::size_t>(shown[k])];
    pages.emplace_back(FidelityViewFile(static_cast<int>(k)),
                       ViewPage(s, static_cast<int>(k), settings, models));
  }
  return pages;
}

}  // namespace foresight
