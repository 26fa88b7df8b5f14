// Forward kinematics of a RobotModel: where each link's frame is for given joint positions.
//   pose_R_child = pose_R_parent * pose_P_J * Rot(axis_J, q)   (URDF: child frame = joint frame)
// R is the root link's frame. No Bullet here; used to stand obstacle robots and to check the
// multibody built from the same model.
#pragma once

#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "models/robot_model.h"

namespace foresight {

// One pose per link (model.links order); q_rad has one entry per joint (fixed joints ignore it).
std::vector<Eigen::Isometry3d> LinkPoses(const RobotModel& model, std::span<const double> q_rad);

// The inertial frame of a link with principal axes: pose_L_C rotated so the inertia is
// diagonal (Bullet wants diagonal inertias), and the diagonal.
struct PrincipalInertia {
  Eigen::Isometry3d pose_L_C = Eigen::Isometry3d::Identity();
  Eigen::Vector3d diagonal_kgm2 = Eigen::Vector3d::Zero();
};
PrincipalInertia PrincipalInertiaOf(const RobotLink& link);

}  // namespace foresight
