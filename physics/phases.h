// The two phases of a physics trial.
//
// Kick phase: the full world with the articulated kicking robot, stepped at the kick time step,
// until the ball has left the robot and rolls without sliding on the carpet (it has "launched"),
// the motion is over without a touch, or the phase's time limit is reached.
// Roll phase: a light world without the kicking robot (carpet, goals, obstacle robots, ball),
// stepped with RollTimeStep, until the ball rests, leaves the carpet (its edge stops it) or the
// roll's time limit is reached.
// Splitting is what makes a trial cheap: the multibody costs far more per step than the ball,
// and after the launch the robot no longer matters (the ball does not come back to it: a
// limitation of the split, see physics_simulator.h).
#pragma once

#include <Eigen/Geometry>
#include <functional>

#include "models/kick_motion.h"
#include "physics/ball_state.h"
#include "physics/carpet.h"
#include "physics/physics_scene.h"

namespace foresight {

struct PhaseEnd {
  BallState ball;
  double t_s = 0.0;
  bool settled = false;   // roll: the ball rests
  bool touched = false;   // kick: the robot touched the ball
  bool launched = false;  // kick: it left the robot and rolls without sliding
  double t_first_touch_s = 0.0;
};

PhaseEnd RunKickPhase(const PhysicsScene& scene, const Carpet& carpet, const KickMotion& motion,
                      const Eigen::Isometry3d& pose_F_root, double speed_factor,
                      const BallState& ball, BallMonitor& monitor);

// Called after every roll step with the world's dispatcher (its contact manifolds) and the ball's
// collision object: probes that need more than the ball's state (robot_impact.h).
using RollStepObserver =
    std::function<void(btDispatcher& dispatcher, const btCollisionObject& ball)>;

PhaseEnd RunRollPhase(const PhysicsScene& scene, const Carpet& carpet, const BallState& ball,
                      double t_start_s, BallMonitor& monitor,
                      const RollStepObserver& observer = {});

}  // namespace foresight
