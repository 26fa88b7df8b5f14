#include "match/kick_executor.h"

#include "planner/coarse_simulator.h"

namespace foresight {

Outcome CoarseKickExecutor::Execute(std::span<const Obstacle> robots, const DrawnState& state,
                                    const ConcreteAction& action) const {
  // The match keeps the paper's coarse contacts (no rebounds).
  const Scene scene{field_, robots, deceleration_mps2_, CoarseRebounds{}};
  return CoarseSimulator(scene).Simulate(state, action);
}

}  // namespace foresight
