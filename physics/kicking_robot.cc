#include "physics/kicking_robot.h"

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <type_traits>

#include "physics/bullet_convert.h"
#include "physics/joint_motor.h"
#include "physics/robot_shapes.h"

namespace foresight {

namespace {

btQuaternion ToBtQuaternion(const Eigen::Matrix3d& rotation) {
  btQuaternion q;
  ToBt(rotation).getRotation(q);
  return q;
}

// Sets up multibody link g - 1 from rigid group g and its moving joint.
void SetUpLink(btMultiBody& body, const RobotModel& model, const std::vector<RigidGroup>& groups,
               int g) {
  const RigidGroup& group = groups[g];
  const RobotJoint& joint = model.joints[group.joint];
  const Eigen::Isometry3d& pose_P_CP = groups[group.parent_group].inertia.pose_L_C;
  const Eigen::Isometry3d& pose_L_CL = group.inertia.pose_L_C;
  const Eigen::Isometry3d pose_CP_J = pose_P_CP.inverse() * group.pose_P_J;
  const Eigen::Matrix3d R_CL_L = pose_L_CL.linear().transpose();
  const Eigen::Matrix3d R_CL_CP = R_CL_L * pose_CP_J.linear().transpose();
  body.setupRevolute(g - 1, group.mass_kg, ToBt(group.inertia.diagonal_kgm2),
                     group.parent_group - 1, ToBtQuaternion(R_CL_CP),
                     ToBt(Eigen::Vector3d(R_CL_L * joint.axis_J)),
                     ToBt(Eigen::Vector3d(pose_CP_J.translation())),
                     ToBt(Eigen::Vector3d(R_CL_L * pose_L_CL.translation())), true);
}

void AddColliders(BulletWorld& world, btMultiBody& body, const RobotModel& model,
                  const std::vector<RigidGroup>& groups, const PhysicsParams& params,
                  const Material& own_contact) {
  const bool floating = params.robot.base == RobotBase::kFloating;
  const int mask = floating ? (kGroupBall | kGroupStatic) : kGroupBall;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const RigidGroup& group = groups[g];
    auto* compound = world.Own(std::make_unique<btCompoundShape>());
    const Eigen::Isometry3d pose_C_L = group.inertia.pose_L_C.inverse();
    for (const auto& [link, pose_L_M] : group.members) {
      AddLinkShapes(world, model.links[link], pose_C_L * pose_L_M, *compound);
    }
    // Bullet solves a joint motor only in the simulation island of its link's collider; a link
    // without one leaves its motor unsolved (the joint swings freely). A group without
    // collision geometry therefore gets a tiny collider that collides with nothing.
    const bool anchor_only = compound->getNumChildShapes() == 0;
    btCollisionShape* shape = compound;
    if (anchor_only) shape = world.Own(std::make_unique<btSphereShape>(0.001));
    const int index = static_cast<int>(g) - 1;
    auto collider = std::make_unique<btMultiBodyLinkCollider>(&body, index);
    collider->setCollisionShape(shape);
    collider->setUserIndex(static_cast<int>(BodyTag::kKicker));
    // Its contacts with the ball are non-speculative through the world's dispatcher; with the
    // carpet they stay speculative (bullet_world.h).
    MakeStriking(*collider, &own_contact);
    if (floating) {
      collider->setCollisionFlags(collider->getCollisionFlags() |
                                  btCollisionObject::CF_HAS_FRICTION_ANCHOR);
    }
    collider->setRestitution(params.materials.restitution.foot);
    collider->setFriction(params.materials.friction.foot);
    btMultiBodyLinkCollider* raw = collider.get();
    if (index < 0) {
      body.setBaseCollider(raw);
    } else {
      body.getLink(index).m_collider = raw;
    }
    world.AddCollider(std::move(collider), kGroupKicker, anchor_only ? 0 : mask);
  }
}

template <typename Names>
void MarkMoving(const RobotModel& model, const Names& names, std::vector<bool>& moving) {
  for (const auto& item : names) {
    const std::string* name = nullptr;
    if constexpr (std::is_same_v<std::decay_t<decltype(item)>, std::string>) {
      name = &item;
    } else {
      name = &item.first;
    }
    const std::optional<int> j = model.FindJoint(*name);
    assert(j.has_value());  // LoadRobot checked them against the model
    moving[*j] = true;
  }
}

}  // namespace

std::vector<bool> KickJoints(const Robot& robot, const KickMotion& motion, RobotBase base) {
  std::vector<bool> moving = MovingJoints(robot.model, motion.joints);
  if (base == RobotBase::kFloating) {
    MarkMoving(robot.model, motion.balance.offsets_rad, moving);
    MarkMoving(robot.model, robot.spec.support_joints, moving);
  }
  return moving;
}

std::vector<bool> MovingJoints(const RobotModel& model, std::span<const std::string> names) {
  std::vector<bool> moving(model.joints.size(), names.empty());
  for (const std::string& name : names) {
    const std::optional<int> j = model.FindJoint(name);
    assert(j.has_value());  // LoadRobot checked motions against the model
    moving[*j] = true;
  }
  return moving;
}

KickingRobot::KickingRobot(BulletWorld& world, const Robot& robot,
                           const Eigen::Isometry3d& pose_F_root, std::span<const double> q_rad,
                           const std::vector<bool>& moving, const PhysicsParams& params)
    : robot_(robot),
      motors_params_(params.motors),
      own_contact_{params.robot.restitution, params.robot.friction},
      standing_q_(q_rad.begin(), q_rad.end()),
      groups_(GroupRigidly(robot.model, q_rad, moving)) {
  const RobotModel& model = robot.model;
  pose_C_root_ = groups_[0].inertia.pose_L_C.inverse();
  const int links = static_cast<int>(groups_.size()) - 1;
  const bool fixed_base = params.robot.base == RobotBase::kFixed;
  auto body = std::make_unique<btMultiBody>(
      links, groups_[0].mass_kg, ToBt(groups_[0].inertia.diagonal_kgm2), fixed_base, false);
  body->setBaseWorldTransform(ToBt(Eigen::Isometry3d(pose_F_root * groups_[0].inertia.pose_L_C)));
  for (int g = 1; g <= links; ++g) SetUpLink(*body, model, groups_, g);
  body->finalizeMultiDof();
  body->setHasSelfCollision(false);
  body_ = world.AddMultiBody(std::move(body));
  for (int g = 1; g <= links; ++g) body_->setJointPos(g - 1, q_rad[groups_[g].joint]);
  AddColliders(world, *body_, model, groups_, params, own_contact_);
  btAlignedObjectArray<btQuaternion> scratch_q;
  btAlignedObjectArray<btVector3> scratch_m;
  body_->forwardKinematics(scratch_q, scratch_m);
  body_->updateCollisionObjectWorldTransforms(scratch_q, scratch_m);

  motors_.assign(model.joints.size(), nullptr);
  for (int g = 1; g <= links; ++g) {
    const int j = groups_[g].joint;
    auto motor = std::make_unique<LineLimitedJointMotor>(body_, g - 1, robot.motors[j]);
    motor->setPositionTarget(q_rad[j], params.motors.position_gain);
    motor->setVelocityTarget(0.0, params.motors.velocity_gain);
    // The motor never aims faster than the joint can turn, whatever its position error (the
    // motions are checked at load; this bounds the catch-up after a lag or a speed draw).
    motor->setRhsClamp(model.joints[j].velocity_radps);
    motors_[j] = motor.get();
    world.AddConstraint(std::move(motor));
  }
}

void KickingRobot::FollowMotion(const KickMotion& motion, double t_s, double speed_factor) {
  if (motion_joint_index_.empty()) {
    // Joint indices and balance offsets per motion joint, looked up once, not every step.
    for (const std::string& name : motion.joints) {
      motion_joint_index_.push_back(*robot_.model.FindJoint(name));
      double offset_rad = 0.0;
      for (const auto& [balance_joint, offset] : motion.balance.offsets_rad) {
        if (balance_joint == name) offset_rad = offset;
      }
      motion_offset_rad_.push_back(offset_rad);
    }
    q_scratch_.resize(motion.joints.size());
    qdot_scratch_.resize(motion.joints.size());
  }
  motion.Sample(t_s * speed_factor, q_scratch_, qdot_scratch_);
  for (std::size_t k = 0; k < motion_joint_index_.size(); ++k) {
    LineLimitedJointMotor* motor = motors_[motion_joint_index_[k]];
    assert(motor != nullptr);  // the robot was built with the motion's joints moving
    const double offset_rad = balance_share_ * motion_offset_rad_[k];
    // A target the offset would push past a limit stops at it (the side kicks swing the
    // kicking leg's hip roll to its limit; shifted, they reach it earlier).
    const RobotJoint& joint = robot_.model.joints[motion_joint_index_[k]];
    const double target_rad =
        offset_rad == 0.0 ? q_scratch_[k]
                          : std::clamp(q_scratch_[k] + offset_rad, joint.lower_rad, joint.upper_rad);
    motor->setPositionTarget(target_rad, motors_params_.position_gain);
    motor->setVelocityTarget(qdot_scratch_[k] * speed_factor, motors_params_.velocity_gain);
  }
}

void KickingRobot::ShiftWeight(const KickMotion& motion, double t_s) {
  const KickBalance& balance = motion.balance;
  balance_share_ = balance.Share(t_s);
  // d/dt (3u^2 - 2u^3) = 6 u (1 - u) / shift_s while the shift lasts.
  const double u = balance.Has() ? std::clamp(t_s / balance.shift_s, 0.0, 1.0) : 1.0;
  const double rate_per_s = balance.Has() ? 6.0 * u * (1.0 - u) / balance.shift_s : 0.0;
  for (const auto& [name, offset_rad] : balance.offsets_rad) {
    const int j = *robot_.model.FindJoint(name);
    LineLimitedJointMotor* motor = motors_[j];
    assert(motor != nullptr);  // built with KickJoints on a floating base
    motor->setPositionTarget(standing_q_[j] + balance_share_ * offset_rad,
                             motors_params_.position_gain);
    motor->setVelocityTarget(rate_per_s * offset_rad, motors_params_.velocity_gain);
  }
}

KickerState KickingRobot::State(const Eigen::Isometry3d& pose_F_start) const {
  KickerState state;
  const Eigen::Isometry3d pose_R0_F = pose_F_start.inverse();
  state.pose_R0_base = pose_R0_F * ToEigen(body_->getBaseWorldTransform());
  state.v_R0_base = pose_R0_F.linear() * ToEigen(body_->getBaseVel());
  state.w_R0_base = pose_R0_F.linear() * ToEigen(body_->getBaseOmega());
  for (int i = 0; i < body_->getNumLinks(); ++i) {
    state.q_rad.push_back(body_->getJointPos(i));
    state.qdot_radps.push_back(body_->getJointVel(i));
  }
  return state;
}

void KickingRobot::Restore(const KickerState& state, const Eigen::Isometry3d& pose_F_start) {
  assert(static_cast<int>(state.q_rad.size()) == body_->getNumLinks());
  body_->setBaseWorldTransform(ToBt(Eigen::Isometry3d(pose_F_start * state.pose_R0_base)));
  body_->setBaseVel(ToBt(Eigen::Vector3d(pose_F_start.linear() * state.v_R0_base)));
  body_->setBaseOmega(ToBt(Eigen::Vector3d(pose_F_start.linear() * state.w_R0_base)));
  for (int i = 0; i < body_->getNumLinks(); ++i) {
    body_->setJointPos(i, state.q_rad[i]);
    body_->setJointVel(i, state.qdot_radps[i]);
  }
  btAlignedObjectArray<btQuaternion> scratch_q;
  btAlignedObjectArray<btVector3> scratch_m;
  body_->forwardKinematics(scratch_q, scratch_m);
  body_->updateCollisionObjectWorldTransforms(scratch_q, scratch_m);
}

double KickingRobot::TiltRad() const {
  const Eigen::Isometry3d pose_F_root = ToEigen(body_->getBaseWorldTransform()) * pose_C_root_;
  return std::acos(std::clamp(pose_F_root.linear()(2, 2), -1.0, 1.0));
}

void KickingRobot::LinkPoses(std::vector<Eigen::Isometry3d>& pose_F_link) const {
  pose_F_link.resize(robot_.model.links.size());
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    // Every group has a collider (AddColliders), placed at the group's inertial frame C.
    const btCollisionObject* collider =
        g == 0 ? body_->getBaseCollider() : body_->getLink(static_cast<int>(g) - 1).m_collider;
    const Eigen::Isometry3d pose_F_L =
        ToEigen(collider->getWorldTransform()) * groups_[g].inertia.pose_L_C.inverse();
    for (const auto& [link, pose_L_member] : groups_[g].members) {
      pose_F_link[link] = pose_F_L * pose_L_member;
    }
  }
}

const std::string& KickingRobot::ContactLinkName(int index) const {
  const RigidGroup& group = groups_.at(static_cast<std::size_t>(index + 1));
  int named = group.link;
  for (const auto& member : group.members) {
    if (!robot_.model.links[member.first].collisions.empty()) named = member.first;
  }
  return robot_.model.links[named].name;
}

std::vector<double> KickingRobot::JointPositions() const {
  std::vector<double> q = standing_q_;
  for (std::size_t g = 1; g < groups_.size(); ++g) {
    q[groups_[g].joint] = body_->getJointPos(static_cast<int>(g) - 1);
  }
  return q;
}

}  // namespace foresight
