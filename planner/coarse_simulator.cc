#include "planner/coarse_simulator.h"

#include "planner/ball_roll.h"

namespace foresight {

Outcome CoarseSimulator::Simulate(const DrawnState& state, const ConcreteAction& action) const {
  if (action.kick_index == kNoKick) return RollBall(world_, state.p_F_ball, Vec2(1.0, 0.0), 0.0);
  const double heading_F =
      state.robot.theta_rad + action.rotation_rad + action.launch_direction_rad;
  return RollBall(world_, state.p_F_ball, UnitVector(heading_F), action.launch_speed_mps,
                  action.launch_offset_m);
}

}  // namespace foresight
