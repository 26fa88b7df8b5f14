#include "match/kick_executor.h"

namespace foresight {

// The match keeps the paper's coarse contacts with posts and nets (no rebounds).
CoarseKickExecutor::CoarseKickExecutor(const FieldSpec& field, double rolling_deceleration_mps2)
    : simulator_(Scene{&field, {}, rolling_deceleration_mps2, CoarseRebounds{}}) {}

Outcome CoarseKickExecutor::Execute(std::span<const Obstacle> /*robots*/, const DrawnState& state,
                                    const ConcreteAction& action) const {
  return simulator_.Simulate(state, action);
}

}  // namespace foresight
