// Deciding over a fixed set of candidate rotations: an evaluator that snaps every rotation the
// strategies ask for to the nearest candidate rotation (on the circle) and remembers what it
// evaluated. A strategy run on it (planner/decision.h) therefore chooses among the candidates,
// and the coarse model and physics, each wrapped in one, decide over the same actions.
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "planner/action_evaluator.h"

namespace foresight {

class CandidateGridEvaluator final : public ActionEvaluator {
 public:
  // `rotations_rad` must not be empty; `inner` must outlive this evaluator.
  CandidateGridEvaluator(ActionEvaluator& inner, std::vector<double> rotations_rad);

  ActionEvaluation Evaluate(int kick_index, double rotation_rad) override;
  // Fewer samples than all: the inner evaluator's, at the snapped rotation (not remembered).
  ActionEvaluation EvaluateFirst(int kick_index, double rotation_rad, int samples) override;
  int sample_count() const override { return inner_.sample_count(); }
  std::vector<Outcome> Outcomes(int kick_index, double rotation_rad) const override;
  double Snap(double rotation_rad) const;

 private:
  ActionEvaluator& inner_;
  std::vector<double> rotations_rad_;
  std::map<std::pair<int, double>, ActionEvaluation> done_;
};

}  // namespace foresight
