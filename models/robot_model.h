// A robot's body as read from its URDF (models/robots/<robot>/<robot>.urdf) with urdfdom, and
// the collision meshes it names read with assimp. Plain data in SI units; physics/ turns it into
// Bullet bodies. Frames: L = a link's frame (URDF link origin), C = the link's inertial (centre
// of mass) frame, J = a joint's frame, S = a collision shape's frame; poses are written
// pose_A_B (B's frame expressed in A).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace foresight {

struct RobotShape {
  enum class Kind { kBox, kSphere, kCylinder, kMesh };
  Kind kind = Kind::kBox;
  Eigen::Isometry3d pose_L_S = Eigen::Isometry3d::Identity();  // URDF <collision><origin>
  Eigen::Vector3d box_size_m = Eigen::Vector3d::Zero();        // kBox: full extents
  double radius_m = 0.0;                                       // kSphere, kCylinder
  double length_m = 0.0;                                       // kCylinder, along S's z
  std::filesystem::path mesh_file;                             // kMesh: resolved path
  std::vector<Eigen::Vector3d> mesh_vertices_S_m;              // kMesh: scaled, in S
  std::vector<std::array<int, 3>> mesh_triangles;              // kMesh: vertex indices
};

struct RobotLink {
  std::string name;
  double mass_kg = 0.0;
  Eigen::Isometry3d pose_L_C = Eigen::Isometry3d::Identity();  // URDF <inertial><origin>
  Eigen::Matrix3d inertia_C_kgm2 = Eigen::Matrix3d::Zero();    // about the COM, in C's axes
  std::vector<RobotShape> collisions;
  int parent_joint = -1;  // index into RobotModel::joints; -1 for the root link
};

struct RobotJoint {
  enum class Kind { kRevolute, kFixed };
  std::string name;
  Kind kind = Kind::kRevolute;
  int parent_link = -1;
  int child_link = -1;
  Eigen::Isometry3d pose_P_J = Eigen::Isometry3d::Identity();  // in the parent link's frame
  Eigen::Vector3d axis_J = Eigen::Vector3d::UnitZ();           // unit vector in J
  double lower_rad = 0.0;                                      // kRevolute only
  double upper_rad = 0.0;
  double effort_nm = 0.0;
  double velocity_radps = 0.0;
};

struct RobotModel {
  std::string name;              // the URDF's <robot name>
  std::filesystem::path source;  // the URDF file
  // Topological order: links[0] is the root, every link comes after its parent; joints[i]
  // is listed in the order of the child links (joints[j].child_link increases with j).
  std::vector<RobotLink> links;
  std::vector<RobotJoint> joints;

  std::optional<int> FindLink(const std::string& name) const;
  std::optional<int> FindJoint(const std::string& name) const;
  double TotalMassKg() const;
};

// Plausibility ranges of a URDF's numbers: far beyond any robot that kicks a ball
// (NAO 5.4 kg and 0.57 m, AIBO 1.6 kg; joint speeds up to 25 rad/s), far below what overflows
// Bullet or hides a unit error (grams or millimetres read as kilograms or metres). Assumptions.
inline constexpr double kMaxLinkMassKg = 100.0;
inline constexpr double kMaxInertiaKgm2 = 100.0;
inline constexpr double kMaxRobotLengthM = 10.0;  // origins, shape sizes, mesh vertices
inline constexpr double kMaxJointEffortNm = 10000.0;
inline constexpr double kMaxJointSpeedRadps = 1000.0;
inline constexpr double kMaxJointAngleRad = 4.0 * 3.14159265358979323846;  // two turns

// Reads a URDF and the meshes it names (paths relative to the URDF's folder). Throws InputError
// naming the file and the element for malformed XML, a missing or empty mesh, a link without
// mass or inertia, a joint type other than revolute or fixed, a revolute joint without limits,
// or a number outside its plausibility range above.
RobotModel LoadRobotModel(const std::filesystem::path& urdf_file);

}  // namespace foresight
