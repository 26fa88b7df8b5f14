// Everything the coarse decision needs for one situation, built once: the scene, the coarse
// simulator and the position value. Decide() is then cheap and can be called with any seed.
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
  SeamActionEvaluator MakeSeamEvaluator(int samples, std::uint64_t seed) const&& = delete;
  CoarseActionEvaluator MakeEvaluator(int samples, std::uint64_t seed) const& {
    return CoarseActionEvaluator(situation_, simulator_.world(), value_, samples, seed);
  }
  // The same through the outcome-simulator seam (for cross-checks and reports).
  SeamActionEvaluator MakeSeamEvaluator(int samples, std::uint64_t seed) const& {
    return SeamActionEvaluator(situation_, simulator_, value_, samples, seed);
  }
  Decision Decide(Strategy strategy, int samples, std::uint64_t seed) const;

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
