#include "physics/robot_kinematics.h"

#include <Eigen/Eigenvalues>
#include <cassert>
#include <cmath>

namespace foresight {

std::vector<Eigen::Isometry3d> LinkPoses(const RobotModel& model, std::span<const double> q_rad) {
  assert(q_rad.size() == model.joints.size());
  std::vector<Eigen::Isometry3d> poses(model.links.size(), Eigen::Isometry3d::Identity());
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const RobotJoint& joint = model.joints[j];
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    if (joint.kind == RobotJoint::Kind::kRevolute) {
      motion.linear() = Eigen::AngleAxisd(q_rad[j], joint.axis_J).toRotationMatrix();
    }
    // Links are in topological order, so the parent's pose is already known.
    poses[joint.child_link] = poses[joint.parent_link] * joint.pose_P_J * motion;
  }
  return poses;
}

PrincipalInertia PrincipalInertiaOf(const RobotLink& link) {
  PrincipalInertia out;
  const Eigen::Matrix3d& inertia = link.inertia_C_kgm2;
  // Off-diagonal terms at round-off level (composite inertias) count as zero, so the frame
  // keeps its axes instead of being permuted by the eigen solver.
  const double eps = 1e-12 * inertia.trace();
  const bool diagonal = std::abs(inertia(0, 1)) <= eps && std::abs(inertia(0, 2)) <= eps &&
                        std::abs(inertia(1, 2)) <= eps;
  out.pose_L_C = link.pose_L_C;
  if (diagonal) {
    out.diagonal_kgm2 = inertia.diagonal();
    return out;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
  Eigen::Matrix3d axes = solver.eigenvectors();
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);  // keep a proper rotation
  out.pose_L_C.linear() = link.pose_L_C.linear() * axes;
  out.diagonal_kgm2 = solver.eigenvalues();
  return out;
}

}  // namespace foresight
