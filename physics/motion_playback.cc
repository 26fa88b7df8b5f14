#include "physics/motion_playback.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/bullet_convert.h"
#include "physics/bullet_world.h"
#include "physics/joint_motor.h"
#include "physics/played_speed.h"

namespace foresight {

void PlayMotionAlone(const Robot& robot, const KickMotion& motion, const PhysicsParams& params,
                     double speed_factor,
                     const std::function<void(const KickingRobot&, double)>& each_step) {
  const double dt = params.steps.kick_time_step_s;
  BulletWorld world(BulletWorld::Kind::kMultiBody,
                    {params.steps.solver_iterations, params.steps.restitution_threshold_mps});
  PhysicsParams fixed = params;
  fixed.robot.base = RobotBase::kFixed;
  const std::vector<double> q = robot.StandingPositions(motion);
  KickingRobot kicker(world, robot, PlanarPose(0, 0, robot.BaseHeightM(motion), 0), q,
                      MovingJoints(robot.model, motion.joints), fixed);
  for (double t = 0.0; t < motion.DurationS() / speed_factor; t += dt) {
    kicker.FollowMotion(motion, t, speed_factor);
    world.world().stepSimulation(dt, 0, dt);
    each_step(kicker, t);
  }
}

double FindPlayedSpeedShare(const Robot& robot, const KickMotion& motion,
                            const PhysicsParams& params, double speed_factor) {
  double worst = 0.0;
  PlayMotionAlone(robot, motion, params, speed_factor, [&](const KickingRobot& kicker, double) {
    for (std::size_t j = 0; j < robot.model.joints.size(); ++j) {
      const LineLimitedJointMotor* motor = kicker.motor(static_cast<int>(j));
      if (motor == nullptr) continue;
      worst = std::max(worst,
                       std::abs(motor->BoundSpeedRadps()) / motor->line().no_load_speed_radps);
    }
  });
  return worst;
}

}  // namespace foresight
