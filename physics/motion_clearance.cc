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

namespace {

// The lowest point over the motion of the links marked in `counted` (model.links order).
// ... sampled from t_begin_s to t_end_s.
MotionClearance LowestOver(const Robot& robot, const KickMotion& motion, double step_s,
                           const std::vector<bool>& counted, double t_begin_s, double t_end_s) {
  std::vector<int> joint_of;
  for (const std::string& name : motion.joints) joint_of.push_back(*robot.model.FindJoint(name));
  std::vector<double> q = robot.StandingPositions(motion);
  std::vector<double> target(motion.joints.size()), speed(motion.joints.size());
  const Eigen::Isometry3d pose_F_root(
      Eigen::Translation3d(0.0, 0.0, robot.BaseHeightM(motion)));
  MotionClearance clearance{std::numeric_limits<double>::infinity(), 0.0, -1, {}};
  const int steps = static_cast<int>(std::ceil((t_end_s - t_begin_s) / step_s));
  for (int i = 0; i <= steps; ++i) {
    const double t_s = std::min(t_begin_s + i * step_s, t_end_s);
    motion.Sample(t_s, target, speed);
    for (std::size_t k = 0; k < joint_of.size(); ++k) q[joint_of[k]] = target[k];
    const std::vector<Eigen::Isometry3d> pose_root_L = LinkPoses(robot.model, q);
    for (std::size_t l = 0; l < robot.model.links.size(); ++l) {
      if (!counted[l]) continue;
      const double z = LowestPointZ(robot.model.links[l], pose_F_root * pose_root_L[l]);
      if (z < clearance.lowest_m) clearance = {z, t_s, static_cast<int>(l), ""};
    }
  }
  if (clearance.link >= 0) clearance.link_name = robot.model.links[clearance.link].name;
  return clearance;
}

}  // namespace

MotionClearance FindMotionClearance(const Robot& robot, const KickMotion& motion, double step_s) {
  return LowestOver(robot, motion, step_s, std::vector<bool>(robot.model.links.size(), true), 0.0,
                    motion.DurationS());
}

MotionClearance FindSwingClearance(const Robot& robot, const KickMotion& motion, double step_s) {
  // A link moves with the motion when turning one of the motion's joints moves it.
  const std::vector<double> q = robot.StandingPositions(motion);
  const std::vector<Eigen::Isometry3d> still = LinkPoses(robot.model, q);
  std::vector<bool> moved(robot.model.links.size(), false);
  for (const std::string& name : motion.joints) {
    std::vector<double> turned = q;
    turned[*robot.model.FindJoint(name)] += 0.1;
    const std::vector<Eigen::Isometry3d> poses = LinkPoses(robot.model, turned);
    for (std::size_t l = 0; l < moved.size(); ++l) {
      if (!poses[l].isApprox(still[l], 1e-12)) moved[l] = true;
    }
  }
  // The lift from the stance and the set-down start and end on the carpet; in between the swing.
  const std::size_t n = motion.keyframes.size();
  if (n < 3) return LowestOver(robot, motion, step_s, moved, 0.0, motion.DurationS());
  return LowestOver(robot, motion, step_s, moved, motion.keyframes[1].time_s,
                    motion.keyframes[n - 2].time_s);
}

}  // namespace foresight
