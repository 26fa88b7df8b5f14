#include "physics/physics_simulator.h"

#include <cassert>

namespace foresight {

PhysicsSimulator::PhysicsSimulator(PhysicsScene scene, const KickModel& kicks)
    : scene_(std::move(scene)) {
  for (const KickSpec& kick : kicks.kicks) {
    const std::optional<int> motion =
        scene_.robot == nullptr ? std::nullopt : scene_.robot->FindMotion(kick.name);
    motion_of_kick_.push_back(motion.value_or(-1));
  }
}

bool PhysicsSimulator::HasMotion(int kick_index) const {
  return kick_index >= 0 && kick_index < static_cast<int>(motion_of_kick_.size()) &&
         motion_of_kick_[kick_index] >= 0;
}

Outcome PhysicsSimulator::Simulate(const DrawnState& state, const ConcreteAction& action) const {
  return Run(state, action, false).outcome;
}

TrialResult PhysicsSimulator::Run(const DrawnState& state, const ConcreteAction& action,
                                  bool record_trace, double scene_rate_hz) const {
  if (action.kick_index == kNoKick) {
    TrialResult result;
    result.outcome.p_F_rest = state.p_F_ball;
    result.outcome.category = ClassifyPosition(scene_.lines, state.p_F_ball);
    result.settled = true;
    return result;
  }
  assert(HasMotion(action.kick_index));
  KickRequest request;
  request.state = state;
  request.motion_index = motion_of_kick_[action.kick_index];
  request.rotation_rad = action.rotation_rad;
  request.stream = action.stream;
  request.record_trace = record_trace;
  request.scene_rate_hz = scene_rate_hz;
  return RunKickTrial(scene_, request);
}

}  // namespace foresight
