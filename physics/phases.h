// The two phases of a physics trial.
//
// Kick phase: the full world with the articulated kicking robot, stepped at the kick time step,
// until the ball has left the robot and rolls without sliding on the carpet (it has "launched"),
// the motion is over without a touch, or the phase's time limit is reached. A robot on a
// floating base starts from its kick's settled weight shift (settled_stance.h) and is watched
// until its motion has ended and it has stood for the balance's settle time after it, within
// the phase's time limit: the trial records whether its torso tilted past the fall tilt at any
// time, and a fall ends the phase at once. The ball, once launched, is handed to the roll phase
// as it was at the launch, and the rest of the watch only asks whether the robot falls
// (fall_watch.h: its own, coarser steps, and an end once the robot stands provably still).
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
#include "physics/scene_recorder.h"

namespace foresight {

struct PhaseEnd {
  BallState ball;
  double t_s = 0.0;
  bool settled = false;   // roll: the ball rests
  bool touched = false;   // kick: the robot touched the ball
  bool launched = false;  // kick: it left the robot and rolls without sliding
  bool fell = false;      // kick: the robot's torso tilted past the fall tilt (floating base)
  // kick: the robot could not take its stance, a post, net or obstacle robot standing where it
  // must (floating base; KickerStaticOverlapM, bullet_world.h): the motion was not played and
  // the ball lies untouched.
  bool blocked = false;
  double stance_overlap_m = 0.0;  // kick: how deep the stance reached into them
  double t_first_touch_s = 0.0;
  // kick: the strike, the first step in which the robot's touch gave the ball a launch's speed
  // (one that would roll it min_launch_roll_m: slower, a touch is a graze); the first touch if
  // none did.
  double t_strike_s = 0.0;
  double max_tilt_rad = 0.0;  // kick: the torso's largest tilt (floating base)
};

// `settled`: the motion's settled weight shift on a floating base (null: the robot starts from
// its stance).
PhaseEnd RunKickPhase(const PhysicsScene& scene, const Carpet& carpet, const KickMotion& motion,
                      const Eigen::Isometry3d& pose_F_root, double speed_factor,
                      const BallState& ball, BallMonitor& monitor,
                      const SettledStance* settled = nullptr, SceneRecorder* recorder = nullptr);

// Called after every roll step with the world's dispatcher (its contact manifolds) and the ball's
// collision object: probes that need more than the ball's state (robot_impact.h).
using RollStepObserver =
    std::function<void(btDispatcher& dispatcher, const btCollisionObject& ball)>;

PhaseEnd RunRollPhase(const PhysicsScene& scene, const Carpet& carpet, const BallState& ball,
                      double t_start_s, BallMonitor& monitor, const RollStepObserver& observer = {},
                      SceneRecorder* recorder = nullptr);

}  // namespace foresight
