// The kicking robot as a Bullet multibody (Featherstone) with a fixed base, built from the
// URDF model, and joint motors that follow a kick motion.
//
// Frames (Bullet's convention): a multibody link's frame sits at its centre of mass C with the
// principal axes of its inertia. For a link L with parent P and joint J (URDF: L = J at q = 0):
//   rot_parent_to_this = R_CL_CP,          joint axis in CL = R_CL_L * axis_J,
//   parent COM to pivot = t(pose_CP_J),    pivot to this COM (in CL) = R_CL_L * t_L_CL.
// Motors: one btMultiBodyJointMotor per revolute joint, its impulse limited by the URDF effort
// times the step; joints the motion does not name hold the standing pose.
#pragma once

#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "models/physics_params.h"
#include "models/robot_spec.h"
#include "physics/bullet_world.h"

class btMultiBody;
class btMultiBodyJointMotor;

namespace foresight {

class KickingRobot {
 public:
  // Stands `robot` with its root link at pose_F_root and joints at q_rad (model.joints order).
  KickingRobot(BulletWorld& world, const Robot& robot, const Eigen::Isometry3d& pose_F_root,
               std::span<const double> q_rad, const PhysicsParams& params, double dt_s);

  // Motor targets for `motion` played at speed_factor (> 1: faster) at simulated time t_s.
  void FollowMotion(const KickMotion& motion, double t_s, double speed_factor);

  // Current joint positions (model.joints order; fixed joints read 0).
  std::vector<double> JointPositions() const;
  btMultiBody& body() { return *body_; }

 private:
  const Robot& robot_;
  MotorParams motors_params_;
  btMultiBody* body_ = nullptr;
  std::vector<btMultiBodyJointMotor*> motors_;  // per model joint; null for fixed joints
  std::vector<double> standing_q_;
  std::vector<int> motion_joint_index_;  // scratch: motion joint -> model joint
  std::vector<double> q_scratch_, qdot_scratch_;
};

}  // namespace foresight
