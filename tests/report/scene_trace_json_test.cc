// The scene trace's format (report/scene_trace_json.h): integers in the documented units that
// read back to within half a unit, quaternions with w >= 0, contacts and bodies complete.
#include "report/scene_trace_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

namespace foresight {
namespace {

SceneTrace TwoFrames() {
  SceneTrace trace;
  trace.rate_hz = 100.0;
  trace.links = {"torso", "r_foot"};
  trace.phases = {"kick", "roll"};
  SceneFrame a;
  a.t_s = 0.01;
  a.ball.p_F = Eigen::Vector3d(0.123456, -1.5, 0.05);
  a.ball.q_F = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()));
  a.w_F_ball = Eigen::Vector3d(0.0, 12.345, 0.0);
  // A turn given with w < 0 is written with w >= 0 (the same turn).
  const Eigen::Quaterniond q(Eigen::AngleAxisd(2.0, Eigen::Vector3d(0, 0.6, 0.8)));
  a.links = {{Eigen::Vector3d(0.1, 0.2, 0.3), q}, {Eigen::Vector3d(-0.00004, 0, 0),
                                                   Eigen::Quaterniond(-q.coeffs())}};
  SceneFrame b = a;
  b.t_s = 0.0234567;
  b.phase = 1;
  b.links.clear();
  trace.frames = {a, b};
  trace.contacts.push_back({0.01, "ball", "r_foot", Eigen::Vector3d(0.1, 0.0, 0.05), 0.0731});
  return trace;
}

TEST(SceneTraceJsonTest, NumbersReadBackWithinHalfAUnit) {
  const nlohmann::json j = nlohmann::json::parse(SceneTraceJson(TwoFrames()));
  EXPECT_EQ(j["format"], kSceneTraceFormat);
  const double m = j["units"]["m"], s = j["units"]["s"], quat = j["units"]["quaternion"];
  ASSERT_EQ(j["t"].size(), 2u);
  EXPECT_NEAR(j["t"][1].get<double>() / s, 0.0234567, 0.5 / s);
  EXPECT_EQ(j["phase"][1], 1);
  EXPECT_NEAR(j["ball"][0][0].get<double>() / m, 0.123456, 0.5 / m);
  EXPECT_NEAR(j["ball"][0][8].get<double>() / j["units"]["rad_per_s"].get<double>(), 12.345,
              0.005);
  ASSERT_EQ(j["links_pose"][0].size(), 14u);
  EXPECT_TRUE(j["links_pose"][1].empty());
  const auto& pose = j["links_pose"][0];
  const Eigen::Quaterniond q(Eigen::AngleAxisd(2.0, Eigen::Vector3d(0, 0.6, 0.8)));
  for (int link = 0; link < 2; ++link) {
    const double w = pose[7 * link + 6].get<double>() / quat;
    EXPECT_GE(w, 0.0);
    // Both links have the same turn (the second was given as -q).
    const double sign = q.w() < 0.0 ? -1.0 : 1.0;
    EXPECT_NEAR(w, sign * q.w(), 0.5 / quat);
    EXPECT_NEAR(pose[7 * link + 4].get<double>() / quat, sign * q.y(), 0.5 / quat);
  }
  EXPECT_EQ(pose[7], 0);  // -0.04 mm rounds to 0 units of 0.1 mm
  ASSERT_EQ(j["contacts"].size(), 1u);
  EXPECT_EQ(j["contacts"][0][2], "r_foot");
  EXPECT_NEAR(j["contacts"][0][6].get<double>() / j["units"]["N_s"].get<double>(), 0.0731, 1e-6);
}

TEST(SceneTraceJsonTest, RobotShapesCarryTheMeshTriangles) {
  RobotModel model;
  model.name = "r";
  RobotLink link;
  link.name = "foot";
  RobotShape mesh;
  mesh.kind = RobotShape::Kind::kMesh;
  mesh.mesh_vertices_S_m = {{0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}};
  mesh.mesh_triangles = {{0, 1, 2}};
  RobotShape box;
  box.box_size_m = Eigen::Vector3d(0.1, 0.2, 0.3);
  link.collisions = {mesh, box};
  model.links = {link};
  const nlohmann::json j = nlohmann::json::parse(RobotShapesJson(model));
  const auto& shapes = j["links"][0]["shapes"];
  ASSERT_EQ(shapes.size(), 2u);
  EXPECT_EQ(shapes[0]["triangles"], nlohmann::json({0, 1, 2}));
  EXPECT_EQ(shapes[0]["vertices"][3], 1000);  // 0.1 m in 0.1 mm
  EXPECT_EQ(shapes[1]["box"], nlohmann::json({1000, 2000, 3000}));
  EXPECT_EQ(shapes[1]["pose"][6], 10000);  // identity: w = 1
}

}  // namespace
}  // namespace foresight
