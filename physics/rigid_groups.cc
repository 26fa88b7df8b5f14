#include "physics/rigid_groups.h"

#include <cassert>

namespace foresight {

namespace {

// Mass, centre of mass (in L) and inertia about it (L's axes) of a group's members.
void Accumulate(const RobotModel& model, RigidGroup& group) {
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  for (const auto& [link, pose_L_M] : group.members) {
    const RobotLink& member = model.links[link];
    group.mass_kg += member.mass_kg;
    weighted += member.mass_kg * (pose_L_M * member.pose_L_C.translation());
  }
  const Eigen::Vector3d com = weighted / group.mass_kg;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (const auto& [link, pose_L_M] : group.members) {
    const RobotLink& member = model.links[link];
    const Eigen::Matrix3d rotation = pose_L_M.linear() * member.pose_L_C.linear();
    const Eigen::Vector3d d = pose_L_M * member.pose_L_C.translation() - com;
    inertia += rotation * member.inertia_C_kgm2 * rotation.transpose() +
               member.mass_kg * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  RobotLink composite;
  composite.pose_L_C = Eigen::Isometry3d::Identity();
  composite.pose_L_C.translation() = com;
  composite.inertia_C_kgm2 = inertia;
  group.inertia = PrincipalInertiaOf(composite);
}

}  // namespace

std::vector<RigidGroup> GroupRigidly(const RobotModel& model, std::span<const double> q_rad,
                                     const std::vector<bool>& moving) {
  assert(moving.size() == model.joints.size());
  const std::vector<Eigen::Isometry3d> pose_root_L = LinkPoses(model, q_rad);
  std::vector<int> group_of(model.links.size(), -1);
  std::vector<RigidGroup> groups(1);
  group_of[0] = 0;
  for (std::size_t i = 1; i < model.links.size(); ++i) {
    const int j = model.links[i].parent_joint;
    const RobotJoint& joint = model.joints[j];
    const int parent_group = group_of[joint.parent_link];
    if (moving[j] && joint.kind == RobotJoint::Kind::kRevolute) {
      RigidGroup group;
      group.link = static_cast<int>(i);
      group.joint = j;
      group.parent_group = parent_group;
      const Eigen::Isometry3d& frame = pose_root_L[groups[parent_group].link];
      group.pose_P_J = frame.inverse() * pose_root_L[joint.parent_link] * joint.pose_P_J;
      group_of[i] = static_cast<int>(groups.size());
      groups.push_back(group);
    } else {
      group_of[i] = parent_group;
    }
  }
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    RigidGroup& group = groups[group_of[i]];
    // The group's own link sits exactly at its frame (no round-off from pose * pose^-1).
    group.members.emplace_back(
        static_cast<int>(i),
        static_cast<int>(i) == group.link
            ? Eigen::Isometry3d::Identity()
            : Eigen::Isometry3d(pose_root_L[group.link].inverse() * pose_root_L[i]));
  }
  for (RigidGroup& group : groups) Accumulate(model, group);
  return groups;
}

}  // namespace foresight
