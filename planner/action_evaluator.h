// Scores candidate actions of one situation: simulate the N drawn samples of the situation,
// value the rest positions, and evaluate the hypothesis (planner/hypothesis.h).
//
// An evaluator owns its drawn samples, so all candidates of a decision share them (common
// random numbers, planner/sampling.h). Two implementations give the same answers:
//   SeamActionEvaluator    any OutcomeSimulator (coarse or physics) through the seam;
//   CoarseActionEvaluator  the coarse model with per-sample work hoisted out of the rotation
//                          search (planner/coarse_action_evaluator.h): the decision's hot path.
#pragma once

#include <cstdint>
#include <vector>

#include "models/outcome.h"
#include "models/situation.h"
#include "planner/hypothesis.h"
#include "planner/position_value.h"
#include "planner/rotation_search.h"
#include "planner/sampling.h"

namespace foresight {

// The situation gives the static parts (field, kicks, evaluation, obstacles); the state estimate
// is the evaluator's own, so one planner can decide for any pose (CoarsePlanner::Decide). An
// evaluator is also a decision's workspace (the rotation search's storage), so one thread
// keeps one evaluator and decides with it without touching the heap.
class ActionEvaluator {
 public:
  explicit ActionEvaluator(const Situation& situation)
      : ActionEvaluator(situation, situation.state) {}
  ActionEvaluator(const Situation& situation, const StateEstimate& state)
      : situation_(situation), state_(state) {
    search_scratch_.Reserve(situation.evaluation.rotation_search);
  }
  virtual ~ActionEvaluator() = default;

  // kick_index == kNoKick: the `none` action (the ball stays where it is).
  virtual ActionEvaluation Evaluate(int kick_index, double rotation_rad) = 0;
  // The hypothesis of the first `samples` samples only (1..sample_count()): a coarse look for
  // searches (planner/rotation_search.h); with sample_count() samples it is Evaluate's.
  virtual ActionEvaluation EvaluateFirst(int kick_index, double rotation_rad, int samples) = 0;
  // For searches over rotations, the first `samples` samples: may stop simulating as soon as
  // the action is certain to be trimmed, and then only too_risky and trimmed_utility (0) are
  // meaningful.
  virtual ActionEvaluation EvaluateForSearch(int kick_index, double rotation_rad, int samples) {
    return EvaluateFirst(kick_index, rotation_rad, samples);
  }
  // N, the samples of a whole hypothesis.
  virtual int sample_count() const = 0;
  // The hypothesis itself: one outcome per sample, for drawing and reports.
  virtual std::vector<Outcome> Outcomes(int kick_index, double rotation_rad) const = 0;

  int kick_count() const { return static_cast<int>(situation_.kicks.kicks.size()); }
  const Situation& situation() const { return situation_; }
  const StateEstimate& state() const { return state_; }
  long long evaluations() const { return evaluations_; }
  // Samples simulated by the evaluations so far (a hypothesis costs its samples).
  long long samples_simulated() const { return samples_simulated_; }
  RotationSearchScratch& search_scratch() { return search_scratch_; }

 protected:
  const Situation& situation_;
  StateEstimate state_;
  long long evaluations_ = 0;
  long long samples_simulated_ = 0;
  RotationSearchScratch search_scratch_;
};

// Adds one simulated outcome to a hypothesis: the potential of every rest position (NaoTH's tie
// rule averages it over all samples), the value of infield ones.
inline void AddOutcome(HypothesisAccumulator& hypothesis, const Outcome& outcome,
                       const PositionValue& value) {
  const double potential = value.Potential(outcome.p_F_rest);
  const bool infield = outcome.category == Category::kInfield;
  hypothesis.Add(outcome.category, infield ? value.ValueOfPotential(potential) : 0.0, potential);
}

// One simulated outcome's utility (eq. 5 for one sample), valuing an infield rest position.
inline double OutcomeUtility(const Outcome& outcome, const PositionValue& value,
                             const EvaluationParams& params) {
  const bool infield = outcome.category == Category::kInfield;
  return OutcomeUtility(outcome.category, infield ? value.Value(outcome.p_F_rest) : 0.0, params);
}

class SeamActionEvaluator final : public ActionEvaluator {
 public:
  SeamActionEvaluator(const Situation& situation, const OutcomeSimulator& simulator,
                      const PositionValue& value, int samples, std::uint64_t seed);

  ActionEvaluation Evaluate(int kick_index, double rotation_rad) override {
    return EvaluateFirst(kick_index, rotation_rad, sample_count());
  }
  ActionEvaluation EvaluateFirst(int kick_index, double rotation_rad, int samples) override;
  int sample_count() const override { return static_cast<int>(samples_.size()); }
  std::vector<Outcome> Outcomes(int kick_index, double rotation_rad) const override;

 private:
  const OutcomeSimulator& simulator_;
  const PositionValue& value_;
  std::vector<DrawnSample> samples_;
};

}  // namespace foresight
