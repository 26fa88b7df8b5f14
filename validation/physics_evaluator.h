// Scoring candidate actions with physics: the hypothesis of an action is M physics trials
// instead of N coarse samples (the same evaluation, planner/hypothesis.h).
//
// Trial i of every candidate draws the same state from the situation's state estimate and the
// same physical perturbations (common random numbers, as the coarse samples do), so candidates
// differ by their action only. Trials run in parallel; results are the same with any thread
// count. Evaluations are remembered by (kick, rotation), so several strategies deciding on the
// same evaluator (validation/candidate_grid.h) pay for each hypothesis once.
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "physics/physics_simulator.h"
#include "planner/action_evaluator.h"
#include "planner/position_value.h"

namespace foresight {

// One candidate's physics hypothesis: per-trial outcomes and utilities (eq. 5 per trial: the
// rest position's value when infield, the goal value for a goal, 0 else), and its evaluation.
struct PhysicsHypothesis {
  ActionEvaluation evaluation;
  std::vector<Outcome> outcomes;
  std::vector<double> utilities;
};

class PhysicsActionEvaluator final : public ActionEvaluator {
 public:
  PhysicsActionEvaluator(const Situation& situation, const PhysicsSimulator& simulator,
                         const PositionValue& value, int trials, std::uint64_t seed, int threads);

  ActionEvaluation Evaluate(int kick_index, double rotation_rad) override;
  // From the remembered hypothesis of all trials (physics runs every trial of a candidate once;
  // the search's coarse looks are summaries of its first trials).
  ActionEvaluation EvaluateFirst(int kick_index, double rotation_rad, int samples) override;
  int sample_count() const override { return static_cast<int>(samples_.size()); }
  std::vector<Outcome> Outcomes(int kick_index, double rotation_rad) const override;
  // Runs the trials if they have not run yet.
  const PhysicsHypothesis& Hypothesis(int kick_index, double rotation_rad);
  // Trial i of a candidate: the one function the scoring runs for every trial; scene_rate_hz >
  // 0 also records the scene (TrialResult::scene), which changes nothing else.
  TrialResult Trial(int kick_index, double rotation_rad, int i, double scene_rate_hz) const;
  // Trial i of a candidate scored already, run again by Trial with the scene recorded, for the
  // 3D viewer. std::logic_error unless its outcome equals the scored trial's bit for bit: the
  // viewer shows the very trial that was scored, or nothing.
  TrialResult Replay(int kick_index, double rotation_rad, int i, double scene_rate_hz);
  long long trials_run() const { return trials_run_; }

 private:
  PhysicsHypothesis Run(int kick_index, double rotation_rad) const;

  const PhysicsSimulator& simulator_;
  const PositionValue& value_;
  int threads_;
  std::vector<DrawnSample> samples_;
  std::map<std::pair<int, double>, PhysicsHypothesis> done_;
  long long trials_run_ = 0;
};

}  // namespace foresight
