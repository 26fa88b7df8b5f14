#include "validation/physics_evaluator.h"

#include <stdexcept>
#include <string>

#include "common/parallel_for.h"

namespace foresight {

PhysicsActionEvaluator::PhysicsActionEvaluator(const Situation& situation,
                                               const PhysicsSimulator& simulator,
                                               const PositionValue& value, int trials,
                                               std::uint64_t seed, int threads)
    : ActionEvaluator(situation), simulator_(simulator), value_(value), threads_(threads) {
  DrawSamples(situation.state, seed, trials, samples_);
}

PhysicsHypothesis PhysicsActionEvaluator::Run(int kick_index, double rotation_rad) const {
  PhysicsHypothesis h;
  h.outcomes.resize(samples_.size());
  const auto run_trial = [&](int i) {
    h.outcomes[i] = Trial(kick_index, rotation_rad, i, 0.0).outcome;
  };
  ParallelFor(static_cast<int>(samples_.size()), kick_index == kNoKick ? 1 : threads_, run_trial);
  HypothesisAccumulator hypothesis;
  for (const Outcome& outcome : h.outcomes) {
    AddOutcome(hypothesis, outcome, value_);
    h.utilities.push_back(OutcomeUtility(outcome, value_, situation_.evaluation));
  }
  h.evaluation = hypothesis.Finish(situation_.evaluation);
  return h;
}

TrialResult PhysicsActionEvaluator::Trial(int kick_index, double rotation_rad, int i,
                                          double scene_rate_hz) const {
  const DrawnSample& sample = samples_[static_cast<std::size_t>(i)];
  if (kick_index == kNoKick) {  // `none`: the ball stays where it lies
    TrialResult none;
    none.outcome.p_F_rest = sample.state.p_F_ball;
    return none;
  }
  const ConcreteAction action = MakeAction(situation_.kicks, kick_index, rotation_rad, sample);
  return simulator_.Run(sample.state, action, false, scene_rate_hz);
}

TrialResult PhysicsActionEvaluator::Replay(int kick_index, double rotation_rad, int i,
                                           double scene_rate_hz) {
  const Outcome& scored =
      Hypothesis(kick_index, rotation_rad).outcomes.at(static_cast<std::size_t>(i));
  TrialResult again = Trial(kick_index, rotation_rad, i, scene_rate_hz);
  if (!SameBits(again.outcome, scored)) {
    throw std::logic_error("physics trial " + std::to_string(i) + " of kick " +
                           std::to_string(kick_index) +
                           " played again with its scene recorded differs from the scored one");
  }
  return again;
}

const PhysicsHypothesis& PhysicsActionEvaluator::Hypothesis(int kick_index, double rotation_rad) {
  const std::pair<int, double> key{kick_index, kick_index == kNoKick ? 0.0 : rotation_rad};
  auto it = done_.find(key);
  if (it == done_.end()) {
    it = done_.emplace(key, Run(key.first, key.second)).first;
    if (key.first >= 0) trials_run_ += static_cast<long long>(samples_.size());
  }
  return it->second;
}

ActionEvaluation PhysicsActionEvaluator::Evaluate(int kick_index, double rotation_rad) {
  ++evaluations_;
  return Hypothesis(kick_index, rotation_rad).evaluation;
}

ActionEvaluation PhysicsActionEvaluator::EvaluateFirst(int kick_index, double rotation_rad,
                                                       int samples) {
  if (samples >= sample_count()) return Evaluate(kick_index, rotation_rad);
  ++evaluations_;
  const PhysicsHypothesis& h = Hypothesis(kick_index, rotation_rad);
  HypothesisAccumulator hypothesis;
  for (int i = 0; i < samples; ++i) {
    AddOutcome(hypothesis, h.outcomes[static_cast<std::size_t>(i)], value_);
  }
  return hypothesis.Finish(situation_.evaluation, sample_count());
}

std::vector<Outcome> PhysicsActionEvaluator::Outcomes(int kick_index, double rotation_rad) const {
  const auto it = done_.find({kick_index, kick_index == kNoKick ? 0.0 : rotation_rad});
  return it != done_.end() ? it->second.outcomes : Run(kick_index, rotation_rad).outcomes;
}

}  // namespace foresight
