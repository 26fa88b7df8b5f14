#include "planner/action_evaluator.h"

#include <algorithm>

namespace foresight {

SeamActionEvaluator::SeamActionEvaluator(const Situation& situation,
                                         const OutcomeSimulator& simulator,
                                         const PositionValue& value, int samples,
                                         std::uint64_t seed)
    : ActionEvaluator(situation), simulator_(simulator), value_(value) {
  DrawSamples(state_, seed, samples, samples_);
}

ActionEvaluation SeamActionEvaluator::EvaluateFirst(int kick_index, double rotation_rad,
                                                    int samples) {
  ++evaluations_;
  const std::size_t count = std::min(samples_.size(), static_cast<std::size_t>(samples));
  samples_simulated_ += static_cast<long long>(count);
  HypothesisAccumulator hypothesis;
  for (std::size_t i = 0; i < count; ++i) {
    const DrawnSample& sample = samples_[i];
    const ConcreteAction action = MakeAction(situation_.kicks, kick_index, rotation_rad, sample);
    AddOutcome(hypothesis, simulator_.Simulate(sample.state, action), value_);
  }
  const EvaluationParams& params = situation_.evaluation;
  return hypothesis.Finish(params, sample_count());
}

std::vector<Outcome> SeamActionEvaluator::Outcomes(int kick_index, double rotation_rad) const {
  std::vector<Outcome> outcomes;
  outcomes.reserve(samples_.size());
  for (const DrawnSample& sample : samples_) {
    outcomes.push_back(simulator_.Simulate(
        sample.state, MakeAction(situation_.kicks, kick_index, rotation_rad, sample)));
  }
  return outcomes;
}

}  // namespace foresight
