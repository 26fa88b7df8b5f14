// Conversions between the project's Eigen types and Bullet's (double-precision build).
#pragma once

#include <LinearMath/btTransform.h>

#include <Eigen/Geometry>

namespace foresight {

inline btVector3 ToBt(const Eigen::Vector3d& v) {
  return btVector3(v.x(), v.y(), v.z());
}
inline Eigen::Vector3d ToEigen(const btVector3& v) {
  return {v.x(), v.y(), v.z()};
}

inline btMatrix3x3 ToBt(const Eigen::Matrix3d& m) {
  return btMatrix3x3(m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1),
                     m(2, 2));
}

inline btTransform ToBt(const Eigen::Isometry3d& pose) {
  return btTransform(ToBt(Eigen::Matrix3d(pose.linear())),
                     ToBt(Eigen::Vector3d(pose.translation())));
}

inline Eigen::Isometry3d ToEigen(const btTransform& pose) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  const btMatrix3x3& b = pose.getBasis();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out.linear()(r, c) = b[r][c];
  }
  out.translation() = ToEigen(pose.getOrigin());
  return out;
}

// The pose of a frame standing on the carpet at (x, y) in F, turned by yaw, raised by z.
inline Eigen::Isometry3d PlanarPose(double x_m, double y_m, double z_m, double yaw_rad) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(x_m, y_m, z_m);
  return pose;
}

}  // namespace foresight
