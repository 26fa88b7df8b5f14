// The kicking robot as a Bullet multibody (Featherstone) with a fixed base, built from the
// URDF model, and joint motors that follow a kick motion. Only the joints the motion moves are
// multibody joints; the links between them are welded into rigid groups (rigid_groups.h).
//
// Frames (Bullet's convention): a multibody link's frame sits at its centre of mass C with the
// principal axes of its inertia. For a group L with parent P and joint J (URDF: L = J at q = 0):
//   rot_parent_to_this = R_CL_CP,          joint axis in CL = R_CL_L * axis_J,
//   parent COM to pivot = t(pose_CP_J),    pivot to this COM (in CL) = R_CL_L * t_L_CL.
// Motors: one per moving joint (joint_motor.h), its torque bounded by the joint motor's
// torque-speed line from the robot's motor table and the speed it aims at by the URDF velocity
// limit.
//
// Base (models/physics_params.h, RobotBase): fixed, the torso is bolted where it stands and the
// links touch only the ball; floating, the robot stands on its own feet (Bullet's floating
// multibody base, 6 more degrees of freedom) and its links also touch the carpet, posts, nets
// and obstacle robots with the robot's own contact parameters (bullet_world.h, MakeStriking).
// A standing robot keeps its balance with the motion's open-loop weight shift (KickBalance,
// models/kick_motion.h), played by ShiftWeight before the motion and held through it.
#pragma once

#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "models/physics_params.h"
#include "models/robot_spec.h"
#include "physics/bullet_world.h"
#include "physics/rigid_groups.h"
#include "physics/kicker_state.h"

class btMultiBody;

namespace foresight {

class LineLimitedJointMotor;

// Which model joints move: the named ones, or every revolute joint when `names` is empty.
std::vector<bool> MovingJoints(const RobotModel& model, std::span<const std::string> names);
// The joints a kick moves on `base`: the motion's; on a floating base also its balance's and the
// robot's support joints (robot.json), which carry it under their motors.
std::vector<bool> KickJoints(const Robot& robot, const KickMotion& motion, RobotBase base);


class KickingRobot {
 public:
  // Stands `robot` with its root link at pose_F_root and joints at q_rad (model.joints order);
  // the joints marked in `moving` get motors, the others are welded at q_rad.
  KickingRobot(BulletWorld& world, const Robot& robot, const Eigen::Isometry3d& pose_F_root,
               std::span<const double> q_rad, const std::vector<bool>& moving,
               const PhysicsParams& params);

  // Motor targets for `motion` played at speed_factor (> 1: faster) at simulated time t_s, with
  // the share of the balance's offsets last set by ShiftWeight added.
  void FollowMotion(const KickMotion& motion, double t_s, double speed_factor);
  // The weight shift of `motion` t_s after it starts: the balance's joints aim at the stance
  // plus the offsets times the shift's share (KickBalance::Share), at the share's rate.
  void ShiftWeight(const KickMotion& motion, double t_s);

  // The state relative to pose_F_start, the root's pose at construction; Restore puts a state
  // back relative to another such pose (the robot must have been built alike).
  KickerState State(const Eigen::Isometry3d& pose_F_start) const;
  void Restore(const KickerState& state, const Eigen::Isometry3d& pose_F_start);
  // The angle between the root link's z axis and the vertical.
  double TiltRad() const;

  // Every model link's pose in F (model.links order), from the multibody's current state.
  void LinkPoses(std::vector<Eigen::Isometry3d>& pose_F_link) const;
  // The name of the link a contact with multibody link `index` (-1: the base) touched: the
  // deepest member of its rigid group with collision geometry (the foot rather than the ankle).
  const std::string& ContactLinkName(int index) const;

  // Current joint positions (model.joints order; welded joints read their standing position).
  std::vector<double> JointPositions() const;
  btMultiBody& body() { return *body_; }
  const btMultiBody& body() const { return *body_; }
  // The motor of model joint j; null for a welded joint.
  const LineLimitedJointMotor* motor(int j) const { return motors_[j]; }

 private:
  const Robot& robot_;
  MotorParams motors_params_;
  Material own_contact_;        // the floating robot's contacts with the carpet and statics
  Eigen::Isometry3d pose_C_root_ = Eigen::Isometry3d::Identity();  // root link in base frame
  double balance_share_ = 0.0;  // of the motion's balance offsets, in FollowMotion
  btMultiBody* body_ = nullptr;
  std::vector<double> standing_q_;
  std::vector<RigidGroup> groups_;              // groups_[g] is multibody link g - 1
  std::vector<LineLimitedJointMotor*> motors_;  // per model joint; null for welded joints
  // The motion FollowMotion plays (one per robot): motion joint -> model joint, and -> the
  // balance's offset on it (0 for none).
  std::vector<int> motion_joint_index_;
  std::vector<double> motion_offset_rad_;
  std::vector<double> q_scratch_, qdot_scratch_;
};

}  // namespace foresight
