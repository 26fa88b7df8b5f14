#include "physics/phases.h"

#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include <algorithm>
#include <cmath>

#include "physics/fall_watch.h"
#include "physics/kicking_robot.h"

namespace foresight {

namespace {

// A ball counts as launched once the robot has not touched it for this long and it rolls.
constexpr double kReleaseTimeS = 0.02;
// Once the motion is over this long without a touch, the kick missed.
constexpr double kMissGraceS = 0.2;

btRigidBody* AddBall(BulletWorld& world, const PhysicsScene& scene, const BallState& state) {
  const BallSpec& spec = scene.field->ball;
  auto* shape = world.Own(std::make_unique<btSphereShape>(spec.radius_m));
  // Bullet's sphere has the inertia of a solid ball; the field says what this ball is.
  const double inertia = spec.inertia_factor * spec.mass_kg * spec.radius_m * spec.radius_m;
  btRigidBody* ball = world.AddDynamic(shape, spec.mass_kg, btVector3(inertia, inertia, inertia),
                                       btTransform::getIdentity(), BodyTag::kBall, kBallMaterial,
                                       kGroupBall, kGroupStatic | kGroupKicker);
  WriteBall(*ball, state);
  return ball;
}

SolverSettings SolverOf(const StepParams& steps) {
  return {steps.solver_iterations, steps.restitution_threshold_mps};
}

bool RollsFreely(const BallState& ball, double radius_m) {
  if (!TouchesCarpet(ball.p_F.z(), radius_m) || std::abs(ball.v_F.z()) > 0.05) return false;
  return IsRolling(ball.SlipSpeed(radius_m), ball.PlanarSpeed());
}

}  // namespace

PhaseEnd RunKickPhase(const PhysicsScene& scene, const Carpet& carpet, const KickMotion& motion,
                      const Eigen::Isometry3d& pose_F_root, double speed_factor,
                      const BallState& ball_start, BallMonitor& monitor,
                      const SettledStance* settled, SceneRecorder* recorder) {
  const StepParams& steps = scene.params.steps;
  const double dt = steps.kick_time_step_s;
  const double radius = scene.field->ball.radius_m;
  const RobotBase base = scene.params.robot.base;
  const bool floating = base == RobotBase::kFloating;
  BulletWorld world(BulletWorld::Kind::kMultiBody, SolverOf(steps));
  AddStatics(world, scene);
  btRigidBody* ball = AddBall(world, scene, ball_start);
  KickingRobot robot(world, *scene.robot, pose_F_root, scene.robot->StandingPositions(motion),
                     KickJoints(*scene.robot, motion, base), scene.params);
  if (floating && motion.balance.Has()) {
    if (settled != nullptr) robot.Restore(settled->state, pose_F_root);
    robot.ShiftWeight(motion, motion.balance.shift_s);  // held through the motion
  }
  PhaseEnd end;
  end.ball = ball_start;
  end.stance_overlap_m = KickerStaticOverlapM(world.world());
  if (end.stance_overlap_m > 0.0) {
    end.blocked = true;
    if (recorder != nullptr)
      recorder->ObserveKick(0.0, 0.0, robot, ball, *world.world().getDispatcher());
    return end;
  }
  const double motion_end_s = motion.DurationS() / speed_factor;
  // A floating robot must still stand this long after its motion.
  const double stand_end_s = motion_end_s + (floating ? motion.balance.settle_s : 0.0);
  const double deceleration = scene.params.carpet.rolling_deceleration_mps2;
  double last_touch_s = 0.0;
  bool struck = false;
  // The kick phase ends by max_kick_time_s; a floating robot is watched on until it has stood
  // its settle time after its motion, however slow the motion's playback.
  const double watch_end_s = std::max(steps.max_kick_time_s, stand_end_s);
  for (double t = 0.0; t < watch_end_s;) {
    robot.FollowMotion(motion, t, speed_factor);
    carpet.ApplyRollingResistance(*ball, radius, dt);
    world.world().stepSimulation(dt, 0, dt);
    t += dt;
    if (recorder != nullptr) {
      recorder->ObserveKick(t, t * speed_factor, robot, ball, *world.world().getDispatcher());
    }
    if (floating) {
      end.max_tilt_rad = std::max(end.max_tilt_rad, robot.TiltRad());
      if (end.max_tilt_rad > scene.params.robot.fall_tilt_rad) {
        end.fell = true;
        end.ball = ReadBall(*ball);  // the ball goes on from where the fall left it
        end.t_s = t;
        break;
      }
    }
    end.ball = ReadBall(*ball);
    end.t_s = t;
    const StepContacts contacts = ContactsOf(*world.world().getDispatcher(), *ball);
    if (contacts.kicker) {
      if (!end.touched) end.t_first_touch_s = t;
      end.touched = true;
      last_touch_s = t;
    }
    monitor.Observe(t, end.ball, contacts);
    // A touch that leaves the ball (nearly) at rest, e.g. the paw grazing it while the motion
    // winds up, is not a launch: the motion goes on and may still strike it.
    const double speed = end.ball.PlanarSpeed();
    const bool out_of_reach = speed * speed >= 2.0 * deceleration * steps.min_launch_roll_m;
    // The strike: the first step in which the robot's touch has given the ball a launch's speed
    // (the same rule that tells a graze from a launch, below).
    if (contacts.kicker && out_of_reach && !struck) {
      end.t_strike_s = t;
      struck = true;
    }
    if (end.touched && t - last_touch_s >= kReleaseTimeS && (out_of_reach || t > motion_end_s) &&
        RollsFreely(end.ball, radius)) {
      end.launched = true;
      if (!floating || t >= stand_end_s) break;
      // The roll phase takes the ball from here; the robot is only watched for a fall.
      world.world().removeRigidBody(ball);
      const WatchEnd watch = WatchForFall(world, robot, motion,
                                          {t, motion_end_s, stand_end_s, speed_factor},
                                          scene.params, end.max_tilt_rad, recorder);
      end.fell = watch.fell;
      end.max_tilt_rad = watch.max_tilt_rad;
      break;
    }
    if (!end.touched && t > motion_end_s + kMissGraceS && (!floating || t >= stand_end_s)) break;
    if (t >= steps.max_kick_time_s && !floating) break;
  }
  if (!struck) end.t_strike_s = end.t_first_touch_s;  // no touch gave a launch's speed
  return end;
}

PhaseEnd RunRollPhase(const PhysicsScene& scene, const Carpet& carpet, const BallState& start,
                      double t_start_s, BallMonitor& monitor, const RollStepObserver& observer,
                      SceneRecorder* recorder) {
  const StepParams& steps = scene.params.steps;
  const double radius = scene.field->ball.radius_m;
  BulletWorld world(BulletWorld::Kind::kRigid, SolverOf(steps));
  AddStatics(world, scene);
  btRigidBody* ball = AddBall(world, scene, start);
  PhaseEnd end;
  end.ball = start;
  end.t_s = t_start_s;
  const double t_limit = t_start_s + steps.max_roll_time_s;
  while (end.t_s < t_limit) {
    const bool on_carpet = TouchesCarpet(end.ball.p_F.z(), radius);
    const bool rests = on_carpet && end.ball.PlanarSpeed() < steps.rest_speed_mps &&
                       std::abs(end.ball.v_F.z()) < steps.rest_speed_mps;
    if (rests || (scene.carpet_has_edge && !WithinCarpet(scene, end.ball.Planar()))) {
      end.settled = true;
      break;
    }
    const double dt = RollTimeStep(scene, end.ball.Planar(), end.ball.v_F.norm(), on_carpet);
    carpet.ApplyRollingResistance(*ball, radius, dt);
    world.world().stepSimulation(dt, 0, dt);
    end.t_s += dt;
    end.ball = ReadBall(*ball);
    monitor.Observe(end.t_s, end.ball, ContactsOf(*world.world().getDispatcher(), *ball));
    if (observer) observer(*world.world().getDispatcher(), *ball);
    if (recorder != nullptr) recorder->ObserveRoll(end.t_s, *ball, *world.world().getDispatcher());
  }
  return end;
}

}  // namespace foresight
