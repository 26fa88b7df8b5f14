// LoadRobotModel: urdfdom parses the URDF, assimp reads the collision meshes, and this file turns
// both into the plain RobotModel, checking every number where it enters.
//
// Link order: depth first from the root; the children of a link follow in the order of the names
// of the joints that connect them (urdfdom keeps joints in a map, so the file's order is lost;
// names are deterministic). urdfdom reports problems through console_bridge, which prints them;
// while parsing, its global output handler is swapped for one that collects the errors (under a
// mutex, so parallel loads do not interleave), and they become the InputError's text.
#include "models/robot_model.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <assimp/Importer.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <new>
#include <sstream>

#include "common/checks.h"
#include "common/data_file.h"
#include "common/error.h"
#include "models/xml_nesting.h"

namespace foresight {
namespace {

// Collects console_bridge messages of level `error` and above instead of printing them.
class ErrorCollector : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char* /*filename*/,
           int /*line*/) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors.push_back(text);
  }
  std::vector<std::string> errors;
};

// Installs an ErrorCollector as console_bridge's handler for the lifetime of this object.
class ScopedConsoleCapture {
 public:
  explicit ScopedConsoleCapture(ErrorCollector* collector) : lock_(Mutex()) {
    previous_level_ = console_bridge::getLogLevel();
    console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_WARN);
    console_bridge::useOutputHandler(collector);
  }
  ~ScopedConsoleCapture() {
    console_bridge::restorePreviousOutputHandler();
    console_bridge::setLogLevel(previous_level_);
  }
  ScopedConsoleCapture(const ScopedConsoleCapture&) = delete;
  ScopedConsoleCapture& operator=(const ScopedConsoleCapture&) = delete;

 private:
  static std::mutex& Mutex() {
    static std::mutex mutex;
    return mutex;
  }
  std::lock_guard<std::mutex> lock_;
  console_bridge::LogLevel previous_level_;
};

[[noreturn]] void Fail(const std::filesystem::path& file, const std::string& problem) {
  throw InputError(file.string() + ": " + problem);
}

// Runs a check from common/checks.h ("field: must be ..., got V") and prefixes file and element.
template <typename Check>
void Require(const std::filesystem::path& file, const std::string& element, Check&& check) {
  try {
    check();
  } catch (const InputError& e) {
    Fail(file, element + ": " + e.what());
  }
}

std::string ReadText(const std::filesystem::path& file) {
  return ReadDataFile(file);
}

// One line out of urdfdom's messages. Its message for a revolute joint without <limit> is
// rewritten into the project's "joint NAME: ..." form.
std::string DescribeUrdfErrors(std::vector<std::string> errors) {
  const std::string kOpen = "Joint [", kNoLimits = "] is of type REVOLUTE but it does not specify";
  for (const std::string& error : errors) {
    const std::size_t close = error.find(kNoLimits);
    if (error.starts_with(kOpen) && close != std::string::npos) {
      return "joint " + error.substr(kOpen.size(), close - kOpen.size()) +
             ": revolute joint has no <limit>";
    }
  }
  if (errors.empty()) errors.push_back("not a valid URDF");
  std::string joined;
  for (const std::string& error : errors) joined += (joined.empty() ? "" : "; ") + error;
  std::replace(joined.begin(), joined.end(), '\n', ' ');
  std::replace(joined.begin(), joined.end(), '\r', ' ');
  return "urdf: " + joined;
}

urdf::ModelInterfaceSharedPtr ParseUrdf(const std::filesystem::path& file) {
  const std::string text = ReadText(file);
  // Before urdfdom: its parser recurses once per level (a stack overflow far below 16 MiB).
  if (const auto problem = XmlNestingProblem(text)) Fail(file, "urdf: " + *problem);
  ErrorCollector collector;
  urdf::ModelInterfaceSharedPtr model;
  {
    ScopedConsoleCapture capture(&collector);
    try {
      model = urdf::parseURDF(text);
    } catch (const std::exception& e) {
      collector.errors.push_back(e.what());
    }
  }
  // urdfdom returns a model for some malformed elements (a bad <inertial>) after logging an error.
  if (model == nullptr || !collector.errors.empty()) {
    Fail(file, DescribeUrdfErrors(collector.errors));
  }
  return model;
}

Eigen::Isometry3d ToIsometry(const urdf::Pose& pose, const std::filesystem::path& file,
                             const std::string& element) {
  const urdf::Vector3& p = pose.position;
  const urdf::Rotation& r = pose.rotation;
  for (double v : {p.x, p.y, p.z, r.x, r.y, r.z, r.w}) {
    if (!std::isfinite(v)) Fail(file, element + ": <origin> must be finite");
  }
  for (double v : {p.x, p.y, p.z}) {
    if (std::abs(v) > kMaxRobotLengthM) {
      Fail(file, element + ": <origin> xyz: must be within " + FormatNumber(kMaxRobotLengthM) +
                     " m, got " + FormatNumber(v));
    }
  }
  Eigen::Isometry3d iso = Eigen::Isometry3d::Identity();
  iso.translation() = Eigen::Vector3d(p.x, p.y, p.z);
  iso.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  return iso;
}

void AppendVertices(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
                    std::vector<Eigen::Vector3d>* vertices,
                    std::vector<std::array<int, 3>>* triangles) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    const int offset = static_cast<int>(vertices->size());
    // Triangles only (aiProcess_Triangulate; points and lines have fewer indices): the viewer
    // draws them, physics uses the vertices' hull.
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      triangles->push_back({offset + static_cast<int>(face.mIndices[0]),
                            offset + static_cast<int>(face.mIndices[1]),
                            offset + static_cast<int>(face.mIndices[2])});
    }
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      vertices->emplace_back(p.x, p.y, p.z);
    }
  }
  for (unsigned i = 0; i < node.mNumChildren; ++i) {
    AppendVertices(scene, *node.mChildren[i], transform, vertices, triangles);
  }
}

// All vertices of all meshes of `path` with the node transforms applied; throws InputError
// "FILE: ELEMENT: problem" when the file is missing, unreadable or empty.
std::vector<Eigen::Vector3d> ReadMeshVertices(const std::filesystem::path& path,
                                              const std::filesystem::path& file,
                                              const std::string& element,
                                              std::vector<std::array<int, 3>>* triangles) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) Fail(file, element + ": file not found");
  Require(file, element, [&] { RequireDataFile(path); });
  Assimp::Importer importer;
  const aiScene* scene = nullptr;
  try {
    scene =
        importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  } catch (const std::bad_alloc&) {
    throw;  // the machine's or the job's memory limit, not a bad file
  } catch (const std::exception& e) {
    Fail(file, element + ": cannot read mesh: " + e.what());
  }
  if (scene == nullptr || scene->mRootNode == nullptr) {
    std::string problem = importer.GetErrorString();
    // Assimp catches its own exceptions and keeps only their text: running out of memory inside
    // it reads "std::bad_alloc", which is the limit's, not the file's.
    if (problem.find("bad_alloc") != std::string::npos) throw std::bad_alloc();
    std::replace(problem.begin(), problem.end(), '\n', ' ');
    Fail(file, element + ": cannot read mesh: " + problem);
  }
  std::vector<Eigen::Vector3d> vertices;
  AppendVertices(*scene, *scene->mRootNode, aiMatrix4x4(), &vertices, triangles);
  if (vertices.empty()) Fail(file, element + ": mesh has no vertices");
  for (const Eigen::Vector3d& v : vertices) {
    if (!v.allFinite()) Fail(file, element + ": mesh has a vertex that is not finite");
    if (v.cwiseAbs().maxCoeff() > kMaxRobotLengthM) {
      Fail(file, element + ": mesh has a vertex farther than " + FormatNumber(kMaxRobotLengthM) +
                     " m from its origin (a unit error?)");
    }
  }
  return vertices;
}

RobotShape ReadMeshShape(const urdf::Mesh& mesh, const std::filesystem::path& file,
                         const std::string& link_element) {
  const std::string element = link_element + ": collision mesh " + mesh.filename;
  if (mesh.filename.find("://") != std::string::npos) {
    Fail(file, element + ": only paths relative to the URDF's folder are supported");
  }
  const Eigen::Vector3d scale(mesh.scale.x, mesh.scale.y, mesh.scale.z);
  // A mirrored mesh (a negative factor) turns its faces inside out: mirror the file instead.
  for (int i = 0; i < 3; ++i) {
    if (!(std::isfinite(scale[i]) && scale[i] > 0.0)) {
      Fail(file, element + ": scale " + std::string(1, "xyz"[i]) +
                     ": must be finite and positive, got " + FormatNumber(scale[i]));
    }
  }
  RobotShape shape;
  shape.kind = RobotShape::Kind::kMesh;
  shape.mesh_file = (file.parent_path() / mesh.filename).lexically_normal();
  shape.mesh_vertices_S_m = ReadMeshVertices(shape.mesh_file, file, element, &shape.mesh_triangles);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(kMaxRobotLengthM), hi = -lo;
  for (Eigen::Vector3d& v : shape.mesh_vertices_S_m) {
    v = v.cwiseProduct(scale);
    if (!(v.cwiseAbs().maxCoeff() <= kMaxRobotLengthM)) {
      Fail(file, element + ": scale: the scaled mesh reaches farther than " +
                     FormatNumber(kMaxRobotLengthM) + " m from its origin (a unit error?)");
    }
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  // As a box's sizes: a mesh flat in one direction (all on one point: in every one) has no
  // volume, and every kick at it would pass through unseen.
  for (int i = 0; i < 3; ++i) {
    if (!(hi[i] > lo[i])) {
      Fail(file, element + ": mesh has no extent in " + std::string(1, "xyz"[i]) +
                     " (every vertex at " + std::string(1, "xyz"[i]) + " = " +
                     FormatNumber(lo[i]) + ")");
    }
  }
  return shape;
}

RobotShape ReadShape(const urdf::Collision& collision, const std::filesystem::path& file,
                     const std::string& link_element) {
  if (collision.geometry == nullptr) Fail(file, link_element + ": <collision> has no <geometry>");
  const urdf::Geometry& geometry = *collision.geometry;
  RobotShape shape;
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const urdf::Vector3& dim = static_cast<const urdf::Box&>(geometry).dim;
      shape.kind = RobotShape::Kind::kBox;
      shape.box_size_m = Eigen::Vector3d(dim.x, dim.y, dim.z);
      const std::string element = link_element + ": collision box";
      Require(file, element, [&] {
        RequirePositive("size x", dim.x);
        RequirePositive("size y", dim.y);
        RequirePositive("size z", dim.z);
        RequireInRange("size x", dim.x, 0.0, kMaxRobotLengthM);
        RequireInRange("size y", dim.y, 0.0, kMaxRobotLengthM);
        RequireInRange("size z", dim.z, 0.0, kMaxRobotLengthM);
      });
      break;
    }
    case urdf::Geometry::SPHERE:
      shape.kind = RobotShape::Kind::kSphere;
      shape.radius_m = static_cast<const urdf::Sphere&>(geometry).radius;
      Require(file, link_element + ": collision sphere", [&] {
        RequirePositive("radius", shape.radius_m);
        RequireInRange("radius", shape.radius_m, 0.0, kMaxRobotLengthM);
      });
      break;
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      shape.kind = RobotShape::Kind::kCylinder;
      shape.radius_m = cylinder.radius;
      shape.length_m = cylinder.length;
      const std::string element = link_element + ": collision cylinder";
      Require(file, element, [&] {
        RequirePositive("radius", shape.radius_m);
        RequirePositive("length", shape.length_m);
        RequireInRange("radius", shape.radius_m, 0.0, kMaxRobotLengthM);
        RequireInRange("length", shape.length_m, 0.0, kMaxRobotLengthM);
      });
      break;
    }
    case urdf::Geometry::MESH:
      shape = ReadMeshShape(static_cast<const urdf::Mesh&>(geometry), file, link_element);
      break;
  }
  shape.pose_L_S = ToIsometry(collision.origin, file, link_element + ": <collision>");
  return shape;
}

RobotLink ReadLink(const urdf::Link& source, const std::filesystem::path& file) {
  const std::string element = "link " + source.name;
  if (source.inertial == nullptr) {
    Fail(file, element + ": no <inertial> (mass and inertia are required)");
  }
  const urdf::Inertial& in = *source.inertial;
  RobotLink link;
  link.name = source.name;
  link.mass_kg = in.mass;
  Require(file, element, [&] {
    RequirePositive("mass", in.mass);
    RequireInRange("mass", in.mass, 0.0, kMaxLinkMassKg);
  });
  link.pose_L_C = ToIsometry(in.origin, file, element + ": <inertial>");
  Require(file, element, [&] {
    RequirePositive("inertia ixx", in.ixx);
    RequirePositive("inertia iyy", in.iyy);
    RequirePositive("inertia izz", in.izz);
    RequireFinite("inertia ixy", in.ixy);
    RequireFinite("inertia ixz", in.ixz);
    RequireFinite("inertia iyz", in.iyz);
    RequireInRange("inertia ixx", in.ixx, 0.0, kMaxInertiaKgm2);
    RequireInRange("inertia iyy", in.iyy, 0.0, kMaxInertiaKgm2);
    RequireInRange("inertia izz", in.izz, 0.0, kMaxInertiaKgm2);
  });
  link.inertia_C_kgm2 << in.ixx, in.ixy, in.ixz,  //
      in.ixy, in.iyy, in.iyz,                     //
      in.ixz, in.iyz, in.izz;
  const double smallest =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(link.inertia_C_kgm2).eigenvalues().minCoeff();
  if (!(smallest > 0.0)) {
    Fail(file, element + ": inertia: must be positive definite, smallest eigenvalue " +
                   FormatNumber(smallest));
  }
  for (const urdf::CollisionSharedPtr& collision : source.collision_array) {
    link.collisions.push_back(ReadShape(*collision, file, element));
  }
  return link;
}

RobotJoint ReadJoint(const urdf::Joint& source, const std::filesystem::path& file) {
  const std::string element = "joint " + source.name;
  RobotJoint joint;
  joint.name = source.name;
  joint.pose_P_J = ToIsometry(source.parent_to_joint_origin_transform, file, element);
  if (source.type == urdf::Joint::FIXED) {
    joint.kind = RobotJoint::Kind::kFixed;
    return joint;
  }
  if (source.type != urdf::Joint::REVOLUTE) {
    static const std::map<int, std::string> kTypeNames = {{urdf::Joint::CONTINUOUS, "continuous"},
                                                          {urdf::Joint::PRISMATIC, "prismatic"},
                                                          {urdf::Joint::FLOATING, "floating"},
                                                          {urdf::Joint::PLANAR, "planar"},
                                                          {urdf::Joint::UNKNOWN, "unknown"}};
    Fail(file, element + ": type " + kTypeNames.at(source.type) +
                   " is not supported (revolute or fixed only)");
  }
  joint.kind = RobotJoint::Kind::kRevolute;
  const Eigen::Vector3d axis(source.axis.x, source.axis.y, source.axis.z);
  if (!axis.allFinite() || !(axis.norm() > 1e-12)) {
    Fail(file, element + ": <axis> must be a finite non-zero vector");
  }
  joint.axis_J = axis.normalized();
  if (source.limits == nullptr) Fail(file, element + ": revolute joint has no <limit>");
  const urdf::JointLimits& limits = *source.limits;
  Require(file, element + ": <limit>", [&] {
    RequireFinite("lower", limits.lower);
    RequireFinite("upper", limits.upper);
    RequirePositive("effort", limits.effort);
    RequirePositive("velocity", limits.velocity);
    RequireInRange("lower", limits.lower, -kMaxJointAngleRad, kMaxJointAngleRad);
    RequireInRange("upper", limits.upper, -kMaxJointAngleRad, kMaxJointAngleRad);
    RequireInRange("effort", limits.effort, 0.0, kMaxJointEffortNm);
    RequireInRange("velocity", limits.velocity, 0.0, kMaxJointSpeedRadps);
  });
  if (!(limits.lower <= limits.upper)) {
    Fail(file, element + ": <limit>: lower " + FormatNumber(limits.lower) +
                   " is greater than upper " + FormatNumber(limits.upper));
  }
  joint.lower_rad = limits.lower;
  joint.upper_rad = limits.upper;
  joint.effort_nm = limits.effort;
  joint.velocity_radps = limits.velocity;
  return joint;
}

// Appends `link` and its subtree depth first, children ordered by the name of their joint.
void AppendSubtree(const urdf::ModelInterface& urdf, const urdf::Link& link, int parent_joint,
                   const std::filesystem::path& file, RobotModel* model) {
  RobotLink robot_link = ReadLink(link, file);
  robot_link.parent_joint = parent_joint;
  const int link_index = static_cast<int>(model->links.size());
  model->links.push_back(std::move(robot_link));

  std::vector<urdf::JointSharedPtr> children = link.child_joints;
  std::sort(children.begin(), children.end(),
            [](const auto& a, const auto& b) { return a->name < b->name; });
  for (const urdf::JointSharedPtr& child : children) {
    RobotJoint joint = ReadJoint(*child, file);
    joint.parent_link = link_index;
    joint.child_link = static_cast<int>(model->links.size());
    const int joint_index = static_cast<int>(model->joints.size());
    model->joints.push_back(std::move(joint));
    const urdf::LinkConstSharedPtr child_link = urdf.getLink(child->child_link_name);
    if (child_link == nullptr) Fail(file, "joint " + child->name + ": no child link");
    AppendSubtree(urdf, *child_link, joint_index, file, model);
  }
}

}  // namespace

std::optional<int> RobotModel::FindLink(const std::string& link_name) const {
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (links[i].name == link_name) return static_cast<int>(i);
  }
  return std::nullopt;
}

std::optional<int> RobotModel::FindJoint(const std::string& joint_name) const {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].name == joint_name) return static_cast<int>(i);
  }
  return std::nullopt;
}

double RobotModel::TotalMassKg() const {
  double total = 0.0;
  for (const RobotLink& link : links) total += link.mass_kg;
  return total;
}

RobotModel LoadRobotModel(const std::filesystem::path& urdf_file) {
  const urdf::ModelInterfaceSharedPtr urdf = ParseUrdf(urdf_file);
  RobotModel model;
  model.name = urdf->getName();
  model.source = urdf_file;
  // urdfdom accepts a joint whose child is its own parent (found by fuzzing); name it here,
  // before the tree walk reports the link only as unreached.
  for (const auto& [name, joint] : urdf->joints_) {
    if (joint->parent_link_name == joint->child_link_name) {
      Fail(urdf_file, "urdf: joint " + name + ": parent and child are the same link " +
                          joint->child_link_name);
    }
  }
  AppendSubtree(*urdf, *urdf->getRoot(), -1, urdf_file, &model);
  if (model.links.size() != urdf->links_.size()) {
    std::string unreached;
    for (const auto& [name, link] : urdf->links_) {
      if (!model.FindLink(name)) unreached += (unreached.empty() ? "" : ", ") + name;
    }
    Fail(urdf_file,
         "urdf: links not connected to the root link " + model.links[0].name + ": " + unreached);
  }
  return model;
}

}  // namespace foresight
