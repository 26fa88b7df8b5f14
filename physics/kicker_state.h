// A kicking robot's state (physics/kicking_robot.h) without Bullet's types, so that the scene
// (physics_scene.h, which other folders include) can hold a settled stance.
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace foresight {

// A robot's state relative to the pose its root link stood at when it was built (frame R0):
// a stance settled once can be restored in every trial wherever it stands (physics is the same
// under a turn and a shift along the carpet).
struct KickerState {
  Eigen::Isometry3d pose_R0_base = Eigen::Isometry3d::Identity();  // the multibody's base frame
  Eigen::Vector3d v_R0_base = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_R0_base = Eigen::Vector3d::Zero();
  std::vector<double> q_rad, qdot_radps;  // per multibody link
};

}  // namespace foresight
