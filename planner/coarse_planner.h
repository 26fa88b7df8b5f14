// Everything the coarse decision needs for one scene, built once: the static world, the coarse
// simulator and the position value. Decide() is then cheap and can be called with any seed and,
// through the StateEstimate overloads, for any pose of the robot and ball on that scene (the
// experiments decide for thousands of poses with one planner).
#pragma once

#include <cstdint>

#include "models/situation.h"
#include "planner/coarse_action_evaluator.h"
#include "planner/coarse_simulator.h"
#include "planner/decision.h"
#include "planner/position_value.h"

namespace foresight {

class CoarsePlanner {
 public:
  // `situation` must outlive the planner.
  explicit CoarsePlanner(const Situation& situation);
  explicit CoarsePlanner(const Situation&& situation) = delete;  // it would dangle

  // The fast evaluator of the decision's hot path. Evaluators refer to the planner, so they
  // cannot be made from a temporary one.
  CoarseActionEvaluator MakeEvaluator(int samples, std::uint64_t seed) const&& = delete;
  CoarseActionEvaluator MakeEvaluator(const StateEstimate&, int, std::uint64_t) const&& = delete;
  SeamActionEvaluator MakeSeamEvaluator(int samples, std::uint64_t seed) const&& = delete;
  CoarseActionEvaluator MakeEvaluator(int samples, std::uint64_t seed) const& {
    return MakeEvaluator(situation_.state, samples, seed);
  }
  CoarseActionEvaluator MakeEvaluator(const StateEstimate& state, int samples,
                                      std::uint64_t seed) const& {
    return CoarseActionEvaluator(situation_, state, simulator_.world(), value_, samples, seed);
  }
  // The same through the outcome-simulator seam (for cross-checks and reports).
  SeamActionEvaluator MakeSeamEvaluator(int samples, std::uint64_t seed) const& {
    return SeamActionEvaluator(situation_, simulator_, value_, samples, seed);
  }
  Decision Decide(Strategy strategy, int samples, std::uint64_t seed) const;
  // The decision for another state on the same scene (state.Validate-like checks are the
  // caller's: the pose must be on the carpet).
  Decision Decide(const StateEstimate& state, Strategy strategy, int samples,
                  std::uint64_t seed) const;
  // The same without touching the heap, for a robot's cycle: `evaluator` (made by this planner's
  // MakeEvaluator) is redrawn for the state and seed, and `out` (see ReserveDecision) is
  // overwritten; both keep their storage, so once they have held `samples` samples and the
  // kicks, a decision allocates nothing (tests/planner_alloc/). Equals the one above.
  void Decide(const StateEstimate& state, Strategy strategy, int samples, std::uint64_t seed,
              CoarseActionEvaluator& evaluator, Decision& out) const;

  const Situation& situation() const { return situation_; }
  const CoarseSimulator& simulator() const { return simulator_; }
  const PositionValue& value() const { return value_; }

 private:
  const Situation& situation_;
  CoarseSimulator simulator_;
  PositionValue value_;
};

Scene MakeScene(const Situation& situation);

}  // namespace foresight
