// Everything the coarse decision needs for one situation, built once: the scene, the coarse
// simulator and the position value. Decide() is then cheap and can be called with any seed.
#pragma once

#include <cstdint>

#include "models/situation.h"
#include "planner/coarse_simulator.h"
#include "planner/decision.h"
#include "planner/position_value.h"

namespace foresight {

class CoarsePlanner {
 public:
  // `situation` must outlive the planner.
  explicit CoarsePlanner(const Situation& situation);

  ActionEvaluator MakeEvaluator(int samples, std::uint64_t seed) const {
    return ActionEvaluator(situation_, simulator_, value_, samples, seed);
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
