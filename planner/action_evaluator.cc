#include "planner/action_evaluator.h"

namespace foresight {

SeamActionEvaluator::SeamActionEvaluator(const Situation& situation,
                                         const OutcomeSimulator& simulator,
                                         const PositionValue& value, int samples,
                                         std::uint64_t seed)
    : ActionEvaluator(situation), simulator_(simulator), value_(value) {
  DrawSamples(state_, seed, samples, samples_);
}

ActionEvaluation SeamActionEvaluator::Evaluate(int kick_index, double rotation_rad) {
  ++evaluations_;
  HypothesisAccumulator hypothesis;
  for (const DrawnSample& sample : samples_) {
    const ConcreteAction action = MakeAction(situation_.kicks, kick_index, rotation_rad, sample);
    AddOutcome(hypothesis, simulator_.Simulate(sample.state, action), value_);
  }
  return hypothesis.Finish(situation_.evaluation);
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
