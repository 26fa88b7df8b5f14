// The tester robot the URDF reader's tests load: a small URDF naming a cube mesh, each test
// writing its own copy (ctest runs tests in parallel processes), and the reader's error message.
#pragma once

#include <filesystem>
#include <string>

#include "models/robot_model.h"
#include "tests/support/model_test_util.h"
#include "tests/support/temp_files.h"

namespace foresight::testing {

// A cube with corners at +-1, written as quads (assimp triangulates them).
inline constexpr const char* kCubeObj = R"(# unit cube
v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
)";

// torso -(NeckYaw)- head and torso -(HipPitch)- thigh -(KneePitch)- foot -(SoleFixed)- sole.
// Links and joints are listed out of order on purpose: the loader orders them itself.
inline constexpr const char* kTesterUrdf = R"(<?xml version="1.0"?>
<robot name="tester">
  <link name="sole">
    <inertial>
      <mass value="0.01"/>
      <inertia ixx="1e-6" ixy="0" ixz="0" iyy="1e-6" iyz="0" izz="1e-6"/>
    </inertial>
  </link>
  <link name="foot">
    <inertial>
      <mass value="0.2"/>
      <inertia ixx="0.0002" ixy="0" ixz="0" iyy="0.0003" iyz="0" izz="0.0004"/>
    </inertial>
    <visual><geometry><box size="9 9 9"/></geometry></visual>
    <collision>
      <origin xyz="0.02 0 -0.01" rpy="0 0 0"/>
      <geometry><mesh filename="CUBE_OBJ" scale="0.5 1 2"/></geometry>
    </collision>
  </link>
  <link name="torso">
    <inertial>
      <origin xyz="0.01 -0.002 0.05" rpy="0 0 0"/>
      <mass value="1.5"/>
      <inertia ixx="0.01" ixy="0.001" ixz="-0.002" iyy="0.02" iyz="0.0005" izz="0.03"/>
    </inertial>
    <collision>
      <origin xyz="0 0 0.1" rpy="0 0 0"/>
      <geometry><box size="0.1 0.2 0.3"/></geometry>
    </collision>
    <collision>
      <geometry><sphere radius="0.04"/></geometry>
    </collision>
  </link>
  <link name="head">
    <inertial>
      <mass value="0.6"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/>
    </inertial>
    <collision><geometry><sphere radius="0.05"/></geometry></collision>
  </link>
  <link name="thigh">
    <inertial>
      <origin xyz="0 0 -0.05" rpy="0 0 0"/>
      <mass value="0.4"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.0002"/>
    </inertial>
    <collision>
      <origin xyz="0 0 -0.05" rpy="0.25 0 0"/>
      <geometry><cylinder radius="0.02" length="0.1"/></geometry>
    </collision>
  </link>
  <joint name="NeckYaw" type="revolute">
    <parent link="torso"/>
    <child link="head"/>
    <origin xyz="0 0 0.126" rpy="0 0 0"/>
    <axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="1.5" velocity="8"/>
  </joint>
  <joint name="SoleFixed" type="fixed">
    <parent link="foot"/>
    <child link="sole"/>
    <origin xyz="0 0 -0.04" rpy="0 0 0"/>
  </joint>
  <joint name="KneePitch" type="revolute">
    <parent link="thigh"/>
    <child link="foot"/>
    <origin xyz="0 0 -0.1" rpy="0 0.5 0"/>
    <axis xyz="0 2 0"/>
    <limit lower="-0.09" upper="2.11" effort="1.6" velocity="6.4"/>
  </joint>
  <joint name="HipPitch" type="revolute">
    <parent link="torso"/>
    <child link="thigh"/>
    <origin xyz="0 0.05 -0.085" rpy="0 0 0"/>
    <axis xyz="0 1 0"/>
    <limit lower="-1.5" upper="0.48" effort="1.6" velocity="6.4"/>
  </joint>
</robot>
)";

// kTesterUrdf (with `from` replaced by `to` when given) written to the temporary folder as
// robot_model_<name>.urdf, next to the cube mesh robot_model_<name>_cube.obj it names where
// the text says CUBE_OBJ. Every test has its own files: ctest runs tests in parallel processes.
inline std::filesystem::path TesterUrdf(const std::string& name, const std::string& from = "",
                                 const std::string& to = "") {
  const std::string cube = "robot_model_" + name + "_cube.obj";
  WriteTempFile(cube, kCubeObj);
  std::string text = from.empty() ? kTesterUrdf : ReplaceOnce(kTesterUrdf, from, to);
  if (text.find("CUBE_OBJ") != std::string::npos) text = ReplaceOnce(text, "CUBE_OBJ", cube);
  return WriteTempFile("robot_model_" + name + ".urdf", text);
}

inline std::string LoadError(const std::filesystem::path& file) {
  return InputErrorMessage([&] { LoadRobotModel(file); });
}

}  // namespace foresight::testing
