#include "physics/motion_clearance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "physics/robot_kinematics.h"

namespace foresight {
namespace {

double LowestPointOfShape(const RobotShape& shape, const Eigen::Isometry3d& pose_F_S) {
  double lowest = std::numeric_limits<double>::infinity();
  switch (shape.kind) {
    case RobotShape::Kind::kMesh:
      for (const Eigen::Vector3d& v : shape.mesh_vertices_S_m) {
        lowest = std::min(lowest, (pose_F_S * v).z());
      }
      return lowest;
    case RobotShape::Kind::kBox:
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d sign((corner & 1) ? 0.5 : -0.5, (corner & 2) ? 0.5 : -0.5,
                                   (corner & 4) ? 0.5 : -0.5);
        lowest = std::min(lowest, (pose_F_S * sign.cwiseProduct(shape.box_size_m)).z());
      }
      return lowest;
    case RobotShape::Kind::kSphere:
      return pose_F_S.translation().z() - shape.radius_m;
    case RobotShape::Kind::kCylinder: {
      // The axis's z component a: the end caps reach |a| L/2 down, the rim sqrt(1 - a^2) r.
      const double axis_z = pose_F_S.linear()(2, 2);
      return pose_F_S.translation().z() - 0.5 * shape.length_m * std::abs(axis_z) -
             shape.radius_m * std::sqrt(std::max(0.0, 1.0 - axis_z * axis_z));
    }
  }
  return lowest;
}

}  // namespace

double LowestPointZ(const RobotLink& link, const Eigen::Isometry3d& pose_F_L) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const RobotShape& shape : link.collisions) {
    lowest = std::min(lowest, LowestPointOfShape(shape, pose_F_L * shape.pose_L_S));
  }
  return lowest;
}

MotionClearance FindMotionClearance(const Robot& robot, const KickMotion& motion, double step_s) {
  std::vector<int> joint_of;
  for (const std::string& name : motion.joints) joint_of.push_back(*robot.model.FindJoint(name));
  std::vector<double> q = robot.StandingPositions(motion);
  std::vector<double> target(motion.joints.size()), speed(motion.joints.size());
  const Eigen::Isometry3d pose_F_root(
      Eigen::Translation3d(0.0, 0.0, robot.BaseHeightM(motion)));
  MotionClearance clearance{std::numeric_limits<double>::infinity(), 0.0, -1};
  const int steps = static_cast<int>(std::ceil(motion.DurationS() / step_s));
  for (int i = 0; i <= steps; ++i) {
    const double t_s = std::min(i * step_s, motion.DurationS());
    motion.Sample(t_s, target, speed);
    for (std::size_t k = 0; k < joint_of.size(); ++k) q[joint_of[k]] = target[k];
    const std::vector<Eigen::Isometry3d> pose_root_L = LinkPoses(robot.model, q);
    for (std::size_t l = 0; l < robot.model.links.size(); ++l) {
      const double z = LowestPointZ(robot.model.links[l], pose_F_root * pose_root_L[l]);
      if (z < clearance.lowest_m) clearance = {z, t_s, static_cast<int>(l), ""};
    }
  }
  clearance.link_name = robot.model.links[clearance.link].name;
  return clearance;
}

}  // namespace foresight
