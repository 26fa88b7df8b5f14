// The URDF reader's refusals: each bad robot ends in one InputError naming the file and the
// element, never a crash or a silently wrong model.
#include "models/robot_model.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "tests/models/tester_urdf.h"
#include "tests/support/temp_files.h"

#include "tests/support/model_test_util.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorMessage;
using testing::LoadError;
using testing::ModelsDir;
using ::testing::Not;
using testing::ReplaceOnce;
using ::testing::StartsWith;
using testing::TesterUrdf;
using testing::WriteTempFile;

TEST(RobotModelTest, RevoluteJointWithoutLimitNamesFileAndJoint) {
  const auto file = TesterUrdf(
      "no_limit", R"(<limit lower="-0.09" upper="2.11" effort="1.6" velocity="6.4"/>)", "");
  EXPECT_EQ(LoadError(file), file.string() + ": joint KneePitch: revolute joint has no <limit>");
}

TEST(RobotModelTest, ContinuousJointIsNotSupported) {
  const auto file = TesterUrdf("continuous", R"(<joint name="KneePitch" type="revolute">)",
                               R"(<joint name="KneePitch" type="continuous">)");
  EXPECT_EQ(LoadError(file), file.string() +
                                 ": joint KneePitch: type continuous is not supported (revolute "
                                 "or fixed only)");
}

TEST(RobotModelTest, PrismaticJointIsNotSupported) {
  const auto file = TesterUrdf("prismatic", R"(<joint name="HipPitch" type="revolute">)",
                               R"(<joint name="HipPitch" type="prismatic">)");
  EXPECT_EQ(LoadError(file), file.string() +
                                 ": joint HipPitch: type prismatic is not supported (revolute or "
                                 "fixed only)");
}

TEST(RobotModelTest, LinkWithoutInertialIsRejected) {
  const auto file = TesterUrdf("no_inertial", R"(<inertial>
      <mass value="0.01"/>
      <inertia ixx="1e-6" ixy="0" ixz="0" iyy="1e-6" iyz="0" izz="1e-6"/>
    </inertial>)",
                               "");
  EXPECT_EQ(LoadError(file),
            file.string() + ": link sole: no <inertial> (mass and inertia are required)");
}

TEST(RobotModelTest, ZeroMassIsRejected) {
  const auto file = TesterUrdf("zero_mass", R"(<mass value="1.5"/>)", R"(<mass value="0"/>)");
  EXPECT_EQ(LoadError(file), file.string() + ": link torso: mass: must be > 0, got 0");
}

// Issue 16: plausibility ranges (models/robot_model.h), with the value and the range.
TEST(RobotModelTest, MassInGramsIsRejected) {
  const auto file = TesterUrdf("mass_grams", R"(<mass value="1.5"/>)", R"(<mass value="1500"/>)");
  EXPECT_EQ(LoadError(file),
            file.string() + ": link torso: mass: must be in [0, 100], got 1500");
}

TEST(RobotModelTest, AbsurdJointSpeedIsRejected) {
  const std::string urdf = testing::ReadText(TesterUrdf("speed_probe", "", ""));
  const std::size_t at = urdf.find("velocity=\"");
  ASSERT_NE(at, std::string::npos);
  const std::size_t end = urdf.find('"', at + 10);
  const auto file = TesterUrdf("absurd_speed", urdf.substr(at, end - at + 1),
                               "velocity=\"1e9\"");
  EXPECT_THAT(LoadError(file), HasSubstr("<limit>: velocity: must be in [0, 1000], got 1e+09"));
}

TEST(RobotModelTest, OriginInMillimetresIsRejected) {
  const auto file = TesterUrdf("origin_mm", R"(<origin xyz="0 0 0.1" rpy="0 0 0"/>)",
                               R"(<origin xyz="0 0 100" rpy="0 0 0"/>)");
  EXPECT_THAT(LoadError(file), HasSubstr("<origin> xyz: must be within 10 m, got 100"));
}

TEST(RobotModelTest, NegativeInertiaDiagonalIsRejected) {
  const auto file =
      TesterUrdf("negative_ixx", R"(ixx="0.01" ixy="0.001")", R"(ixx="-0.01" ixy="0.001")");
  EXPECT_EQ(LoadError(file), file.string() + ": link torso: inertia ixx: must be > 0, got -0.01");
}

TEST(RobotModelTest, InertiaThatIsNotPositiveDefiniteIsRejected) {
  // Diagonal 0.001, off-diagonal 0.002: eigenvalues 0.001 +- 0.002, one negative.
  const auto file = TesterUrdf(
      "indefinite", R"(<inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/>)",
      R"(<inertia ixx="0.001" ixy="0.002" ixz="0" iyy="0.001" iyz="0" izz="0.001"/>)");
  EXPECT_THAT(LoadError(file),
              StartsWith(file.string() + ": link head: inertia: must be positive definite"));
}

TEST(RobotModelTest, NonNumericMassIsReportedFromUrdfdomWithFileAndLink) {
  const auto file = TesterUrdf("nan_mass", R"(<mass value="0.6"/>)", R"(<mass value="nan"/>)");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": urdf: "));
  EXPECT_THAT(message, HasSubstr("[nan]"));
  EXPECT_THAT(message, HasSubstr("Link [head]"));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

TEST(RobotModelTest, FlatBoxIsRejected) {
  const auto file =
      TesterUrdf("flat_box", R"(<box size="0.1 0.2 0.3"/>)", R"(<box size="0.1 0 0.3"/>)");
  EXPECT_EQ(LoadError(file),
            file.string() + ": link torso: collision box: size y: must be > 0, got 0");
}

TEST(RobotModelTest, NegativeSphereRadiusIsRejected) {
  const auto file =
      TesterUrdf("negative_radius", R"(<sphere radius="0.05"/>)", R"(<sphere radius="-0.05"/>)");
  EXPECT_EQ(LoadError(file),
            file.string() + ": link head: collision sphere: radius: must be > 0, got -0.05");
}

TEST(RobotModelTest, CylinderWithoutLengthIsRejected) {
  const auto file = TesterUrdf("zero_length", R"(length="0.1")", R"(length="0")");
  EXPECT_EQ(LoadError(file),
            file.string() + ": link thigh: collision cylinder: length: must be > 0, got 0");
}

TEST(RobotModelTest, LowerLimitAboveUpperIsRejected) {
  const auto file =
      TesterUrdf("crossed_limits", R"(lower="-1.5" upper="0.48")", R"(lower="0.5" upper="0.48")");
  EXPECT_EQ(LoadError(file),
            file.string() + ": joint HipPitch: <limit>: lower 0.5 is greater than upper 0.48");
}

TEST(RobotModelTest, ZeroEffortAndVelocityAreRejected) {
  const auto no_effort =
      TesterUrdf("zero_effort", R"(effort="1.5" velocity="8")", R"(effort="0" velocity="8")");
  EXPECT_EQ(LoadError(no_effort),
            no_effort.string() + ": joint NeckYaw: <limit>: effort: must be > 0, got 0");
  const auto no_velocity =
      TesterUrdf("zero_velocity", R"(effort="1.5" velocity="8")", R"(effort="1.5" velocity="0")");
  EXPECT_EQ(LoadError(no_velocity),
            no_velocity.string() + ": joint NeckYaw: <limit>: velocity: must be > 0, got 0");
}

TEST(RobotModelTest, ZeroAxisIsRejected) {
  const auto file = TesterUrdf("zero_axis", R"(<axis xyz="0 2 0"/>)", R"(<axis xyz="0 0 0"/>)");
  EXPECT_EQ(LoadError(file),
            file.string() + ": joint KneePitch: <axis> must be a finite non-zero vector");
}

TEST(RobotModelTest, MissingMeshNamesLinkAndPath) {
  const auto file = TesterUrdf("missing_mesh", "CUBE_OBJ", "meshes/no_such.obj");
  EXPECT_EQ(LoadError(file),
            file.string() + ": link foot: collision mesh meshes/no_such.obj: file not found");
}

TEST(RobotModelTest, UnreadableMeshNamesLinkPathAndAssimpsReason) {
  WriteTempFile("robot_model_junk.xyz", "junk\n");
  const auto file = TesterUrdf("junk_mesh", "CUBE_OBJ", "robot_model_junk.xyz");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() +
                                  ": link foot: collision mesh robot_model_junk.xyz: cannot read "
                                  "mesh: "));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

TEST(RobotModelTest, MeshWithoutVerticesIsRejected) {
  WriteTempFile("robot_model_empty.stl", "solid empty\nendsolid empty\n");
  const auto file = TesterUrdf("empty_mesh", "CUBE_OBJ", "robot_model_empty.stl");
  EXPECT_EQ(
      LoadError(file),
      file.string() + ": link foot: collision mesh robot_model_empty.stl: mesh has no vertices");
}

// A mesh with every vertex on one point (or flat) has no volume: each kick at it silently
// missed. Refused as a box of size 0 is.
TEST(RobotModelTest, MeshWithoutExtentIsRejected) {
  WriteTempFile("robot_model_point.obj",
                "v 0.5 0.25 0.125\nv 0.5 0.25 0.125\nv 0.5 0.25 0.125\nf 1 2 3\n");
  const auto point = TesterUrdf("point_mesh", "CUBE_OBJ", "robot_model_point.obj");
  EXPECT_EQ(LoadError(point), point.string() +
                                  ": link foot: collision mesh robot_model_point.obj: mesh has no "
                                  "extent in x (every vertex at x = 0.25)");
  WriteTempFile("robot_model_flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto flat = TesterUrdf("flat_mesh", "CUBE_OBJ", "robot_model_flat.obj");
  EXPECT_THAT(LoadError(flat), HasSubstr("mesh has no extent in z (every vertex at z = 0)"));
}

TEST(RobotModelTest, PackageUrisAreNotSupported) {
  const auto file = TesterUrdf("package_uri", "CUBE_OBJ", "package://tester/meshes/cube.obj");
  EXPECT_EQ(LoadError(file), file.string() +
                                 ": link foot: collision mesh package://tester/meshes/cube.obj: "
                                 "only paths relative to the URDF's folder are supported");
}

TEST(RobotModelTest, ZeroMeshScaleIsRejected) {
  const auto file = TesterUrdf("zero_scale", R"(scale="0.5 1 2")", R"(scale="0.5 1 0")");
  EXPECT_EQ(LoadError(file), file.string() +
                                 ": link foot: collision mesh robot_model_zero_scale_cube.obj: "
                                 "scale z: must "
                                 "be finite and positive, got 0");
}

// A mirrored, absurd or huge scale: refused with the mesh named, never played.
TEST(RobotModelTest, MeshScaleHasARange) {
  const struct {
    const char* name;
    const char* scale;
    const char* message;
  } cases[] = {
      {"mirrored", R"(scale="-1 1 1")", "scale x: must be finite and positive, got -1"},
      {"huge", R"(scale="1e308 1 1")", "the scaled mesh reaches farther than 10 m"},
      {"hundredfold", R"(scale="100 100 100")", "the scaled mesh reaches farther than 10 m"},
  };
  for (const auto& c : cases) {
    const auto file = TesterUrdf(std::string("scale_") + c.name, R"(scale="0.5 1 2")", c.scale);
    EXPECT_THAT(LoadError(file), ::testing::HasSubstr(c.message)) << c.name;
    EXPECT_THAT(LoadError(file), ::testing::StartsWith(file.string() + ": link foot: collision mesh"))
        << c.name;
  }
}

TEST(RobotModelTest, TwoRootsAreRejected) {
  // Without its joint, the head is a second root.
  const auto file = TesterUrdf("two_roots", R"(<joint name="NeckYaw" type="revolute">
    <parent link="torso"/>
    <child link="head"/>
    <origin xyz="0 0 0.126" rpy="0 0 0"/>
    <axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="1.5" velocity="8"/>
  </joint>)",
                               "");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": urdf: "));
  EXPECT_THAT(message, HasSubstr("root"));
  EXPECT_THAT(message, HasSubstr("[head]"));
}

TEST(RobotModelTest, JointWhoseParentIsItsChildIsRejected) {
  // The long urdf fuzz run found this input (fuzz/seeds/urdf_self_loop_leak.urdf): urdfdom
  // accepts the joint's link as its own parent, and must not reach the tree walk.
  const auto file = TesterUrdf("self_loop", R"(<parent link="torso"/>
    <child link="head"/>)",
                               R"(<parent link="head"/>
    <child link="head"/>)");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": urdf: "));
  EXPECT_EQ(message, file.string() + ": urdf: joint NeckYaw: parent and child are the same link head");
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

TEST(RobotModelTest, RobotWithoutLinksIsRejected) {
  const auto file = WriteTempFile("robot_model_no_links.urdf", R"(<robot name="empty"></robot>)");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": urdf: "));
  EXPECT_THAT(message, HasSubstr("No link elements"));
}

TEST(RobotModelTest, MalformedXmlIsOneLineNamingTheFile) {
  const auto file =
      WriteTempFile("robot_model_malformed.urdf", "<robot name=\"r\">\n  <link name=\"a\"/\n");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": urdf: "));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

// urdfdom's XML parser recurses per level: 100,000 nested elements (1.3 MB) overflowed its
// stack. They are refused before urdfdom sees them, in one line naming the file.
TEST(RobotModelTest, DeeplyNestedXmlIsRefusedBeforeUrdfdom) {
  std::string text = "<?xml version=\"1.0\"?>\n<robot name=\"r\">\n";
  for (int i = 0; i < 100000; ++i) text += "<link name=\"a\">";
  for (int i = 0; i < 100000; ++i) text += "</link>";
  text += "</robot>\n";
  const auto file = WriteTempFile("robot_model_deep.urdf", text);
  EXPECT_EQ(LoadError(file),
            file.string() + ": urdf: elements nested deeper than 64 levels (line 3)");
}

TEST(RobotModelTest, MissingFileCannotBeOpened) {
  const std::filesystem::path file = ModelsDir() / "robots" / "no_such_robot.urdf";
  EXPECT_EQ(LoadError(file), file.string() + ": cannot open file");
}

TEST(RobotModelTest, UrdfdomMessagesAreCapturedNotPrinted) {
  const auto file = TesterUrdf("quiet", R"(<mass value="0.6"/>)", R"(<mass value="heavy"/>)");
  ::testing::internal::CaptureStderr();
  const std::string message = LoadError(file);
  const std::string printed = ::testing::internal::GetCapturedStderr();
  EXPECT_THAT(message, HasSubstr("[heavy]"));
  EXPECT_EQ(printed, "");
}

TEST(RobotModelTest, ParallelLoadsKeepTheirOwnMessages) {
  // Each thread parses a URDF with its own error; the captured message must be that file's.
  constexpr int kThreads = 4;
  std::vector<std::filesystem::path> files;
  for (int i = 0; i < kThreads; ++i) {
    files.push_back(TesterUrdf("parallel_" + std::to_string(i), R"(<mass value="0.6"/>)",
                               "<mass value=\"bad" + std::to_string(i) + "\"/>"));
  }
  std::vector<std::string> messages(kThreads);
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i) {
    threads.emplace_back([&, i] {
      for (int repeat = 0; repeat < 20; ++repeat) {
        try {
          LoadRobotModel(files[i]);
        } catch (const InputError& e) {
          if (messages[i].empty() || messages[i] == e.what()) {
            messages[i] = e.what();
          } else {
            messages[i] = "inconsistent: " + std::string(e.what());
          }
        }
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int i = 0; i < kThreads; ++i) {
    EXPECT_THAT(messages[i], StartsWith(files[i].string() + ": urdf: "));
    EXPECT_THAT(messages[i], HasSubstr("[bad" + std::to_string(i) + "]"));
    EXPECT_THAT(messages[i], Not(HasSubstr("inconsistent")));
  }
}

// The shipped robots (models/robots/), written from published link lengths and masses.

}  // namespace
}  // namespace foresight
