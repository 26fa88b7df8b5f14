// The fidelity comparison: how well the coarse model ranks and chooses kicks against physics.
//
// Per situation, every candidate (each kick with a motion, at each of the set's rotations) is
// scored three ways, all by the utility of eq. 5 (Mellmann & Schlotter):
//   coarse     the coarse model with the robot's N samples (what the robot does),
//   converged  the coarse model with many samples (the model's own answer, sampling error gone),
//   physics    M Bullet trials from the same belief (ground truth, with a t interval).
// Metrics, each for coarse and converged (so the model's error is told from the sampling error):
//   Kendall tau-b between the rankings of the candidates;
//   top-1 agreement: the choice's physics utility is at least the lower end of the physics
//     optimum's interval;
//   regret: physics utility of the physics optimum minus that of the choice.
// Decisions: every strategy decides over the candidates (validation/candidate_grid.h) once
// with the coarse model and once with physics evaluations; agreement means the same kick (or
// none) and the same rotation.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/shard.h"
#include "models/physics_params.h"
#include "planner/decision.h"
#include "report/viewer_page.h"
#include "stats/statistics.h"
#include "validation/fidelity_set.h"

namespace foresight {

struct FidelitySettings {
  int coarse_samples = 0;  // <= 0: the evaluation file's N
  int converged_samples = 2000;
  int physics_trials = 30;
  std::uint64_t seed = 1;
  int threads = 0;
  double confidence = 0.95;
  std::filesystem::path physics_file;      // empty: MODELS/physics/<field>.json
  std::optional<RobotBase> base;           // replaces the physics files' robot base
  std::function<void(int, int)> progress;  // (situations done, total)
  // Only situation i with shard.Owns(i) runs; the result then holds those, in set
  // order, without the aggregates: validation/fidelity_shard.h merges the shards.
  Shard shard;
};

struct CandidateScore {
  int kick_index = 0;
  double rotation_rad = 0.0;
  ActionEvaluation coarse, converged, physics;
  Interval physics_ci;          // of the physics utility
  StatusCounts physics_status;  // trials that missed the ball or did not settle (still scored)
};

struct StrategyAgreement {
  Strategy strategy = Strategy::kOptimalAll;
  int coarse_kick = kNoKick, physics_kick = kNoKick;
  double coarse_rotation_rad = 0.0, physics_rotation_rad = 0.0;
  bool agree = false;
  double regret = 0.0;  // physics utility of the physics decision minus the coarse decision's
};

struct ChoiceMetrics {
  int choice = 0;  // index into candidates
  double tau_b = 0.0;
  bool top1 = false;
  double regret = 0.0;
};

struct SituationFidelity {
  std::string situation_class;
  std::string file;
  Situation situation;
  std::vector<CandidateScore> candidates;
  int physics_best = 0;
  ChoiceMetrics coarse, converged;
  std::vector<StrategyAgreement> decisions;
  std::vector<Outcome> coarse_outcomes;   // the coarse choice's N coarse samples
  std::vector<Outcome> physics_outcomes;  // ... and its physics trials
  long long physics_trials_run = 0;
  StatusCounts physics_status;  // over all candidates
  // The 3D viewer's trials (validation/fidelity_views.h), recorded while the situation ran; only
  // a situation that may be among the worst shown keeps them.
  std::vector<ViewerTrial> views;
};

struct MeanWithInterval {
  int n = 0;
  double mean = 0.0;
  Interval ci;
};

struct ClassSummary {
  std::string situation_class;  // "all" for every situation
  int situations = 0;
  MeanWithInterval tau_coarse, tau_converged, regret_coarse, regret_converged;
  MeanWithInterval top1_coarse, top1_converged;  // shares, Wilson intervals
};

struct StrategyAgreementSummary {
  Strategy strategy = Strategy::kOptimalAll;
  MeanWithInterval agreement;  // share, Wilson interval
  MeanWithInterval regret;
};

struct FidelityResult {
  std::vector<SituationFidelity> situations;
  std::vector<ClassSummary> classes;  // "all" first, then by class in order of appearance
  std::vector<StrategyAgreementSummary> strategies;
  int coarse_samples = 0;
  long long physics_trials_run = 0;
  StatusCounts physics_status;  // over all situations
};

FidelityResult RunFidelity(const FidelitySet& set, const std::filesystem::path& models_dir,
                           const FidelitySettings& settings);

// The totals and aggregates of a result whose `situations` are complete (RunFidelity does this
// for a whole run).
void FinishFidelity(FidelityResult& result, double confidence);

// The coarse samples N of a run: the setting, or the first situation's evaluation file's.
int FidelityCoarseSamples(const FidelitySet& set, const FidelitySettings& settings);

// Whether situation a is worse than b: larger coarse regret, then lower tau (NaN after every
// number), then neither (the earlier in the set comes first). A strict weak order, so the worst
// few of a whole run are among the worst few of each shard's situations.
bool WorseSituation(const SituationFidelity& a, const SituationFidelity& b);

// The situations ordered from worst to best by WorseSituation, ties in set order.
std::vector<int> WorstFirst(const std::vector<SituationFidelity>& situations);
std::vector<int> WorstFirst(const FidelityResult& result);

}  // namespace foresight
