#include "planner/coarse_planner.h"

namespace foresight {

Scene MakeScene(const Situation& situation) {
  return Scene{&situation.field, situation.obstacles, situation.kicks.rolling_deceleration_mps2,
               situation.evaluation.rebounds};
}

CoarsePlanner::CoarsePlanner(const Situation& situation)
    : situation_(situation),
      simulator_(MakeScene(situation)),
      value_(situation.evaluation.potential, situation.field) {}

Decision CoarsePlanner::Decide(Strategy strategy, int samples, std::uint64_t seed) const {
  return Decide(situation_.state, strategy, samples, seed);
}

Decision CoarsePlanner::Decide(const StateEstimate& state, Strategy strategy, int samples,
                               std::uint64_t seed) const {
  CoarseActionEvaluator evaluator = MakeEvaluator(state, samples, seed);
  return foresight::Decide(evaluator, strategy);
}

void CoarsePlanner::Decide(const StateEstimate& state, Strategy strategy, int samples,
                           std::uint64_t seed, CoarseActionEvaluator& evaluator,
                           Decision& out) const {
  evaluator.Redraw(state, samples, seed);
  foresight::Decide(evaluator, strategy, out);
}

}  // namespace foresight
