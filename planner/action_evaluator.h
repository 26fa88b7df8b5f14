// Scores candidate actions of one situation: simulate the N drawn samples through an
// OutcomeSimulator, value the rest positions, and evaluate the hypothesis.
//
// The evaluator owns the drawn samples, so all candidates share them (common random numbers,
// see planner/sampling.h). It works against the seam, so the same code scores candidates with
// the coarse model or with physics.
#pragma once

#include <cstdint>
#include <vector>

#include "models/outcome.h"
#include "models/situation.h"
#include "planner/hypothesis.h"
#include "planner/position_value.h"
#include "planner/sampling.h"

namespace foresight {

class ActionEvaluator {
 public:
  ActionEvaluator(const Situation& situation, const OutcomeSimulator& simulator,
                  const PositionValue& value, int samples, std::uint64_t seed);

  // kick_index < 0: the `none` action (the ball stays where it is).
  ActionEvaluation Evaluate(int kick_index, double rotation_rad);
  // The hypothesis itself: one outcome per sample, for drawing and reports.
  std::vector<Outcome> Outcomes(int kick_index, double rotation_rad) const;

  int kick_count() const { return static_cast<int>(situation_.kicks.kicks.size()); }
  const Situation& situation() const { return situation_; }
  long long evaluations() const { return evaluations_; }

 private:
  const Situation& situation_;
  const OutcomeSimulator& simulator_;
  const PositionValue& value_;
  std::vector<DrawnSample> samples_;
  long long evaluations_ = 0;
};

}  // namespace foresight
