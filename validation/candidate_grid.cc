#include "validation/candidate_grid.h"

#include <cmath>
#include <stdexcept>

#include "common/geometry.h"

namespace foresight {

CandidateGridEvaluator::CandidateGridEvaluator(ActionEvaluator& inner,
                                               std::vector<double> rotations_rad)
    : ActionEvaluator(inner.situation(), inner.state()),
      inner_(inner),
      rotations_rad_(std::move(rotations_rad)) {
  if (rotations_rad_.empty()) throw std::invalid_argument("CandidateGridEvaluator: no rotations");
}

double CandidateGridEvaluator::Snap(double rotation_rad) const {
  double best = rotations_rad_.front();
  double best_gap = 10.0;
  for (double candidate : rotations_rad_) {
    const double gap = std::abs(WrapAngle(candidate - rotation_rad));
    if (gap < best_gap - 1e-12) {
      best = candidate;
      best_gap = gap;
    }
  }
  return best;
}

ActionEvaluation CandidateGridEvaluator::Evaluate(int kick_index, double rotation_rad) {
  ++evaluations_;
  const std::pair<int, double> key{kick_index, kick_index == kNoKick ? 0.0 : Snap(rotation_rad)};
  auto it = done_.find(key);
  if (it == done_.end()) it = done_.emplace(key, inner_.Evaluate(key.first, key.second)).first;
  return it->second;
}

ActionEvaluation CandidateGridEvaluator::EvaluateFirst(int kick_index, double rotation_rad,
                                                       int samples) {
  if (samples >= sample_count()) return Evaluate(kick_index, rotation_rad);
  ++evaluations_;
  return inner_.EvaluateFirst(kick_index, kick_index == kNoKick ? 0.0 : Snap(rotation_rad),
                              samples);
}

std::vector<Outcome> CandidateGridEvaluator::Outcomes(int kick_index, double rotation_rad) const {
  return inner_.Outcomes(kick_index, kick_index == kNoKick ? 0.0 : Snap(rotation_rad));
}

}  // namespace foresight
