#include "tools/motion_mirror.h"

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "common/error.h"
#include "physics/robot_kinematics.h"

namespace foresight {

namespace {

// Two unit axes count as equal within this (assumption: a URDF writes its axes to a few digits;
// a mirror pair that differs by more is a modelling error, not rounding).
constexpr double kAxisTolerance = 1e-6;

std::string Partner(const RobotSpec& spec, const std::string& joint) {
  const auto swapped = [&](const std::string& from, const std::string& to) {
    return joint.compare(0, from.size(), from) == 0 ? to + joint.substr(from.size()) : "";
  };
  if (std::string other = swapped(spec.left_prefix, spec.right_prefix); !other.empty()) return other;
  if (std::string other = swapped(spec.right_prefix, spec.left_prefix); !other.empty()) return other;
  return joint;
}

Eigen::Vector3d AxisInRoot(const RobotModel& model, int joint) {
  const std::vector<double> zero(model.joints.size(), 0.0);
  const std::vector<Eigen::Isometry3d> poses = LinkPoses(model, zero);
  const RobotJoint& j = model.joints[static_cast<std::size_t>(joint)];
  return (poses[static_cast<std::size_t>(j.parent_link)] * j.pose_P_J).linear() * j.axis_J;
}

std::vector<std::pair<std::string, double>> MirrorNamed(
    const Robot& robot, const std::vector<std::pair<std::string, double>>& values) {
  std::vector<std::pair<std::string, double>> mirrored;
  for (const auto& [name, value] : values) {
    const MirroredJoint m = MirrorJoint(robot, name);
    mirrored.emplace_back(m.name, m.sign * value);
  }
  return mirrored;
}

}  // namespace

MirroredJoint MirrorJoint(const Robot& robot, const std::string& joint_name) {
  const std::string where = "robot '" + robot.spec.name + "': ";
  if (robot.spec.left_prefix.empty()) {
    throw InputError(where + "mirror_prefixes: not given, so its motions cannot be mirrored");
  }
  const std::string partner = Partner(robot.spec, joint_name);
  const std::optional<int> j = robot.model.FindJoint(joint_name);
  const std::optional<int> p = robot.model.FindJoint(partner);
  if (!j || !p) {
    throw InputError(where + "joint '" + joint_name + "' or its mirror '" + partner +
                     "' is not in " + robot.model.source.string());
  }
  const Eigen::Vector3d s_a = AxisInRoot(robot.model, *j).cwiseProduct(Eigen::Vector3d(1, -1, 1));
  const Eigen::Vector3d a_p = AxisInRoot(robot.model, *p);
  if ((a_p + s_a).norm() < kAxisTolerance) return {partner, 1.0};
  if ((a_p - s_a).norm() < kAxisTolerance) return {partner, -1.0};
  throw InputError(where + "joints '" + joint_name + "' and '" + partner +
                   "' do not turn about mirrored axes, so no motion of one mirrors onto the other");
}

KickMotion MirrorMotion(const Robot& robot, const KickMotion& motion, const std::string& name) {
  KickMotion mirrored = motion;
  mirrored.name = name;
  mirrored.p_R_ball.y() = -motion.p_R_ball.y();
  mirrored.stance.pose_rad = MirrorNamed(robot, motion.stance.pose_rad);
  mirrored.balance.offsets_rad = MirrorNamed(robot, motion.balance.offsets_rad);
  for (std::size_t i = 0; i < motion.joints.size(); ++i) {
    const MirroredJoint m = MirrorJoint(robot, motion.joints[i]);
    mirrored.joints[i] = m.name;
    for (KickKeyframe& k : mirrored.keyframes) k.positions_rad[i] *= m.sign;
  }
  return mirrored;
}

}  // namespace foresight
