// The Bullet implementation of the outcome-simulator seam (models/outcome.h): each call runs a
// whole physics trial, the robot kicking the ball with the motion of the action's kick.
//
// The coarse launch (launch_speed_mps, launch_direction_rad) of the action is ignored: the
// ball's launch comes out of the simulated kick, perturbed only by the physical causes drawn
// from action.stream. Known limits: the kicking robot is left out of the world once the ball has
// launched, so a ball that bounces back to it passes through; obstacle robots stand still.
#pragma once

#include <vector>

#include "models/kick_model.h"
#include "models/outcome.h"
#include "physics/physics_scene.h"
#include "physics/trial.h"

namespace foresight {

class PhysicsSimulator final : public OutcomeSimulator {
 public:
  // Kicks of `kicks` are matched to the robot's motions by name.
  PhysicsSimulator(PhysicsScene scene, const KickModel& kicks);

  // Whether kick `kick_index` has a motion; simulating one that has none is a programming error
  // (check first, and report it as bad input).
  bool HasMotion(int kick_index) const;

  Outcome Simulate(const DrawnState& state, const ConcreteAction& action) const override;
  // scene_rate_hz > 0 also records the whole scene (TrialResult::scene) at that rate.
  TrialResult Run(const DrawnState& state, const ConcreteAction& action, bool record_trace,
                  double scene_rate_hz = 0.0) const;

  const PhysicsScene& scene() const { return scene_; }

 private:
  PhysicsScene scene_;
  std::vector<int> motion_of_kick_;
};

}  // namespace foresight
