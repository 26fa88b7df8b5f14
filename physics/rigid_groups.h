// Welding a robot for one motion: links that the motion does not move relative to each other
// form one rigid body, so the multibody has one link per moving joint instead of one per URDF
// link (the NAO's forward kick: 3 links instead of 24). Joints outside the motion are held
// exactly at their standing positions instead of by motors (a rigid hold, not a compliant one).
//
// Composite inertia of the members m about the group's centre of mass c (parallel axes):
//   I = sum_m [ R_m I_m R_m^T + m_m (|d_m|^2 1 - d_m d_m^T) ],  d_m = c_m - c,
// then rotated to its principal axes (PrincipalInertia).
#pragma once

#include <Eigen/Geometry>
#include <span>
#include <utility>
#include <vector>

#include "models/robot_model.h"
#include "physics/robot_kinematics.h"

namespace foresight {

struct RigidGroup {
  int link = 0;           // the model link whose frame is the group's frame L
  int joint = -1;         // the moving model joint into the group; -1 for the root group
  int parent_group = -1;  // -1 for the root group
  Eigen::Isometry3d pose_P_J = Eigen::Isometry3d::Identity();  // joint frame in the parent's L
  double mass_kg = 0.0;
  PrincipalInertia inertia;                                // pose_L_C and the diagonal
  std::vector<std::pair<int, Eigen::Isometry3d>> members;  // model link and pose_L_member
};

// groups[0] is the root's group; a group comes after its parent. `moving[j]` says whether model
// joint j moves (fixed joints never do); q_rad holds every joint's standing position.
std::vector<RigidGroup> GroupRigidly(const RobotModel& model, std::span<const double> q_rad,
                                     const std::vector<bool>& moving);

}  // namespace foresight
