#include "planner/action_evaluator.h"

namespace foresight {

ActionEvaluator::ActionEvaluator(const Situation& situation, const OutcomeSimulator& simulator,
                                 const PositionValue& value, int samples, std::uint64_t seed)
    : situation_(situation), simulator_(simulator), value_(value) {
  DrawSamples(situation.state, seed, samples, samples_);
}

ActionEvaluation ActionEvaluator::Evaluate(int kick_index, double rotation_rad) {
  ++evaluations_;
  HypothesisAccumulator hypothesis;
  for (const DrawnSample& sample : samples_) {
    const ConcreteAction action = MakeAction(situation_.kicks, kick_index, rotation_rad, sample);
    const Outcome outcome = simulator_.Simulate(sample.state, action);
    if (outcome.category == Category::kInfield) {
      const double potential = value_.Potential(outcome.p_F_rest);
      hypothesis.Add(outcome.category, value_.ValueOfPotential(potential), potential);
    } else {
      hypothesis.Add(outcome.category, 0.0, 0.0);
    }
  }
  return hypothesis.Finish(situation_.evaluation);
}

std::vector<Outcome> ActionEvaluator::Outcomes(int kick_index, double rotation_rad) const {
  std::vector<Outcome> outcomes;
  outcomes.reserve(samples_.size());
  for (const DrawnSample& sample : samples_) {
    outcomes.push_back(simulator_.Simulate(
        sample.state, MakeAction(situation_.kicks, kick_index, rotation_rad, sample)));
  }
  return outcomes;
}

}  // namespace foresight
