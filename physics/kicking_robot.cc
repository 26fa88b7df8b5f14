#include "physics/kicking_robot.h"

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <cassert>

#include "physics/bullet_convert.h"
#include "physics/robot_kinematics.h"
#include "physics/robot_shapes.h"

namespace foresight {

namespace {

btQuaternion ToBtQuaternion(const Eigen::Matrix3d& rotation) {
  btQuaternion q;
  ToBt(rotation).getRotation(q);
  return q;
}

// Sets up multibody link `i` (model link i + 1) from its joint.
void SetUpLink(btMultiBody& body, const RobotModel& model,
               const std::vector<PrincipalInertia>& inertias, int link) {
  const RobotLink& child = model.links[link];
  const RobotJoint& joint = model.joints[child.parent_joint];
  const Eigen::Isometry3d& pose_P_CP = inertias[joint.parent_link].pose_L_C;
  const Eigen::Isometry3d& pose_L_CL = inertias[link].pose_L_C;
  const Eigen::Isometry3d pose_CP_J = pose_P_CP.inverse() * joint.pose_P_J;
  const Eigen::Matrix3d R_CL_L = pose_L_CL.linear().transpose();
  const Eigen::Matrix3d R_CL_CP = R_CL_L * pose_CP_J.linear().transpose();
  const btQuaternion rot_parent_to_this = ToBtQuaternion(R_CL_CP);
  const btVector3 parent_com_to_pivot = ToBt(Eigen::Vector3d(pose_CP_J.translation()));
  const btVector3 pivot_to_com = ToBt(Eigen::Vector3d(R_CL_L * pose_L_CL.translation()));
  const btVector3 inertia = ToBt(inertias[link].diagonal_kgm2);
  const int parent = joint.parent_link - 1;  // multibody index; -1 is the base
  if (joint.kind == RobotJoint::Kind::kRevolute) {
    body.setupRevolute(link - 1, child.mass_kg, inertia, parent, rot_parent_to_this,
                       ToBt(Eigen::Vector3d(R_CL_L * joint.axis_J)), parent_com_to_pivot,
                       pivot_to_com, true);
  } else {
    body.setupFixed(link - 1, child.mass_kg, inertia, parent, rot_parent_to_this,
                    parent_com_to_pivot, pivot_to_com, true);
  }
}

void AddColliders(BulletWorld& world, btMultiBody& body, const RobotModel& model,
                  const std::vector<PrincipalInertia>& inertias, const PhysicsParams& params) {
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    btCollisionShape* shape = MakeLinkShape(world, model.links[i], inertias[i].pose_L_C.inverse());
    // Bullet solves a joint motor only in the simulation island of its link's collider; a link
    // without one leaves its motor unsolved (the joint swings freely). Links without collision
    // geometry therefore get a tiny collider that collides with nothing.
    const bool anchor_only = shape == nullptr;
    if (anchor_only) shape = world.Own(std::make_unique<btSphereShape>(0.001));
    const int index = static_cast<int>(i) - 1;
    auto collider = std::make_unique<btMultiBodyLinkCollider>(&body, index);
    collider->setCollisionShape(shape);
    collider->setUserIndex(static_cast<int>(BodyTag::kKicker));
    collider->setRestitution(params.materials.robot_restitution);
    collider->setFriction(params.materials.robot_friction);
    btMultiBodyLinkCollider* raw = collider.get();
    if (index < 0) {
      body.setBaseCollider(raw);
    } else {
      body.getLink(index).m_collider = raw;
    }
    world.AddCollider(std::move(collider), kGroupKicker, anchor_only ? 0 : kGroupBall);
  }
}

}  // namespace

KickingRobot::KickingRobot(BulletWorld& world, const Robot& robot,
                           const Eigen::Isometry3d& pose_F_root, std::span<const double> q_rad,
                           const PhysicsParams& params, double dt_s)
    : robot_(robot), motors_params_(params.motors), standing_q_(q_rad.begin(), q_rad.end()) {
  const RobotModel& model = robot.model;
  assert(q_rad.size() == model.joints.size());
  std::vector<PrincipalInertia> inertias;
  for (const RobotLink& link : model.links) inertias.push_back(PrincipalInertiaOf(link));
  const int links = static_cast<int>(model.links.size()) - 1;
  auto body = std::make_unique<btMultiBody>(links, model.links[0].mass_kg,
                                            ToBt(inertias[0].diagonal_kgm2), true, false);
  body->setBaseWorldTransform(ToBt(Eigen::Isometry3d(pose_F_root * inertias[0].pose_L_C)));
  for (int i = 1; i <= links; ++i) SetUpLink(*body, model, inertias, i);
  body->finalizeMultiDof();
  body->setHasSelfCollision(false);
  body_ = world.AddMultiBody(std::move(body));
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    body_->setJointPos(model.joints[j].child_link - 1, q_rad[j]);
  }
  AddColliders(world, *body_, model, inertias, params);
  btAlignedObjectArray<btQuaternion> scratch_q;
  btAlignedObjectArray<btVector3> scratch_m;
  body_->forwardKinematics(scratch_q, scratch_m);
  body_->updateCollisionObjectWorldTransforms(scratch_q, scratch_m);

  motors_.assign(model.joints.size(), nullptr);
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const RobotJoint& joint = model.joints[j];
    if (joint.kind != RobotJoint::Kind::kRevolute) continue;
    auto motor = std::make_unique<btMultiBodyJointMotor>(body_, joint.child_link - 1, 0.0,
                                                         joint.effort_nm * dt_s);
    motor->setPositionTarget(q_rad[j], params.motors.position_gain);
    motor->setVelocityTarget(0.0, params.motors.velocity_gain);
    motors_[j] = motor.get();
    world.AddConstraint(std::move(motor));
  }
}

void KickingRobot::FollowMotion(const KickMotion& motion, double t_s, double speed_factor) {
  if (motion_joint_index_.empty()) {
    for (const std::string& name : motion.joints) {
      const std::optional<int> j = robot_.model.FindJoint(name);
      assert(j.has_value());  // LoadRobot checked the motion against the model
      motion_joint_index_.push_back(*j);
    }
    q_scratch_.resize(motion.joints.size());
    qdot_scratch_.resize(motion.joints.size());
  }
  motion.Sample(t_s * speed_factor, q_scratch_, qdot_scratch_);
  for (std::size_t k = 0; k < motion_joint_index_.size(); ++k) {
    btMultiBodyJointMotor* motor = motors_[motion_joint_index_[k]];
    if (motor == nullptr) continue;
    motor->setPositionTarget(q_scratch_[k], motors_params_.position_gain);
    motor->setVelocityTarget(qdot_scratch_[k] * speed_factor, motors_params_.velocity_gain);
  }
}

std::vector<double> KickingRobot::JointPositions() const {
  std::vector<double> q(robot_.model.joints.size(), 0.0);
  for (std::size_t j = 0; j < q.size(); ++j) {
    if (robot_.model.joints[j].kind == RobotJoint::Kind::kRevolute) {
      q[j] = body_->getJointPos(robot_.model.joints[j].child_link - 1);
    }
  }
  return q;
}

}  // namespace foresight
