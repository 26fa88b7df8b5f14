// The coarse model behind the outcome-simulator seam: the kick's drawn launch, turned into the
// field frame, rolled analytically (planner/ball_roll.h).
#pragma once

#include "models/outcome.h"
#include "planner/coarse_world.h"

namespace foresight {

class CoarseSimulator final : public OutcomeSimulator {
 public:
  explicit CoarseSimulator(const Scene& scene) : world_(CoarseWorld::Build(scene)) {}

  // Launch direction in F: robot heading + rotation around the ball + drawn direction in R.
  Outcome Simulate(const DrawnState& state, const ConcreteAction& action) const override;

  const CoarseWorld& world() const { return world_; }

 private:
  CoarseWorld world_;
};

}  // namespace foresight
