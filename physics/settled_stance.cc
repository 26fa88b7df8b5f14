#include "physics/settled_stance.h"

#include <algorithm>
#include <cassert>

#include "physics/bullet_convert.h"
#include "physics/bullet_world.h"
#include "physics/carpet.h"
#include "physics/kicking_robot.h"

namespace foresight {

SettledStance SettleBalance(const Robot& robot, const KickMotion& motion,
                            const PhysicsParams& params) {
  assert(motion.balance.Has());
  PhysicsParams floating = params;
  floating.robot.base = RobotBase::kFloating;
  const StepParams& steps = params.steps;
  BulletWorld world(BulletWorld::Kind::kMultiBody,
                    {steps.solver_iterations, steps.restitution_threshold_mps});
  AddCarpetPlane(world, params.materials);
  const Eigen::Isometry3d pose_F_start = PlanarPose(0.0, 0.0, robot.BaseHeightM(motion), 0.0);
  KickingRobot kicker(world, robot, pose_F_start, robot.StandingPositions(motion),
                      KickJoints(robot, motion, RobotBase::kFloating), floating);
  SettledStance settled;
  const double dt = steps.kick_time_step_s;
  const int step_count = static_cast<int>(motion.balance.DurationS() / dt + 0.5);
  for (int i = 0; i < step_count; ++i) {
    kicker.ShiftWeight(motion, i * dt);
    world.world().stepSimulation(dt, 0, dt);
    settled.max_tilt_rad = std::max(settled.max_tilt_rad, kicker.TiltRad());
  }
  settled.fell = settled.max_tilt_rad > params.robot.fall_tilt_rad;
  settled.state = kicker.State(pose_F_start);
  return settled;
}

SettledStances SettleStances(const Robot& robot, const PhysicsParams& params) {
  SettledStances stances(robot.motions.size());
  if (params.robot.base != RobotBase::kFloating) return stances;
  for (std::size_t m = 0; m < robot.motions.size(); ++m) {
    const KickMotion& motion = robot.motions[m];
    if (motion.balance.Has()) stances[m] = SettleBalance(robot, motion, params);
  }
  return stances;
}

}  // namespace foresight
