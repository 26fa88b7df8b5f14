#include "models/robot_spec.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "common/checks.h"
#include "common/geometry.h"
#include "tests/support/model_test_util.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorMessage;
using testing::ModelsDir;
using testing::ReplaceOnce;
using ::testing::StartsWith;

constexpr const char* kSpec = R"({
  "name": "tester",
  "notes": "a two-joint leg for the loader tests",
  "urdf": "tester.urdf",
  "base_height_m": 0.3,
  "standing_pose_deg": {"KneePitch": 40.0, "HipPitch": -20.0},
  "kicks": [
    {"name": "forward", "motion": "motions/forward.json"},
    {"name": "side", "motion": "motions/side.json"}
  ],
  "trial_variation": {
    "placement_sigma_x_m": 0.01,
    "placement_sigma_y_m": 0.02,
    "placement_sigma_theta_deg": 2.0,
    "motion_speed_sigma_rel": 0.05
  },
  "motors": {
    "types": {"leg": {"stall_torque_nm": 2.0, "no_load_speed_radps": 7.5, "source": "test"}},
    "joints": {"HipPitch": "leg", "KneePitch": "leg"}
  }
})";

// base -(HipPitch)- thigh -(KneePitch)- shank -(SoleFixed)- sole.
constexpr const char* kUrdf = R"(<robot name="tester">
  <link name="base"><inertial><mass value="1.0"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="thigh"><inertial><mass value="0.3"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <link name="shank"><inertial><mass value="0.2"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <link name="sole"><inertial><mass value="0.1"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <joint name="HipPitch" type="revolute"><parent link="base"/><child link="thigh"/>
    <axis xyz="0 1 0"/><limit lower="-1.5" upper="0.5" effort="1" velocity="6"/></joint>
  <joint name="KneePitch" type="revolute"><parent link="thigh"/><child link="shank"/>
    <axis xyz="0 1 0"/><limit lower="0" upper="2" effort="1" velocity="6"/></joint>
  <joint name="SoleFixed" type="fixed"><parent link="shank"/><child link="sole"/></joint>
</robot>
)";

constexpr const char* kForward = R"({
  "name": "forward", "ball_x_m": 0.15, "ball_y_m": -0.05,
  "joints": ["KneePitch", "HipPitch"],
  "keyframes": [
    {"time_s": 0.0, "positions_deg": [40.0, -20.0]},
    {"time_s": 0.35, "positions_deg": [100.0, -60.0]},
    {"time_s": 0.7, "positions_deg": [40.0, -20.0]}
  ]
})";

constexpr const char* kSide = R"({
  "name": "side", "ball_x_m": 0.1, "ball_y_m": 0.1, "joints": ["HipPitch"],
  "keyframes": [{"time_s": 0.0, "positions_deg": [-20.0]}, {"time_s": 0.5, "positions_deg": [10.0]}]
})";

struct Edit {
  std::string file;  // "robot.json", "tester.urdf", "motions/forward.json", "motions/side.json"
  std::string from, to;
};

// A models folder of its own for the test `test` (ctest runs tests in parallel processes) with
// robots/tester/ holding the files above, `edit` applied; returns the models folder.
std::filesystem::path TesterModels(const std::string& test, const Edit& edit = {}) {
  const std::filesystem::path models =
      std::filesystem::temp_directory_path() / "foresight_tests" / ("robot_spec_" + test);
  const std::filesystem::path dir = models / "robots" / "tester";
  std::filesystem::create_directories(dir / "motions");
  const std::vector<std::pair<std::string, std::string>> files = {
      {"robot.json", kSpec},
      {"tester.urdf", kUrdf},
      {"motions/forward.json", kForward},
      {"motions/side.json", kSide}};
  for (const auto& [name, text] : files) {
    const std::string written = name == edit.file ? ReplaceOnce(text, edit.from, edit.to) : text;
    std::ofstream(dir / name) << written;
  }
  return models;
}

std::filesystem::path SpecFile(const std::filesystem::path& models) {
  return models / "robots" / "tester" / "robot.json";
}

std::string SpecError(const std::string& test, const std::string& from, const std::string& to,
                      std::filesystem::path* file) {
  *file = SpecFile(TesterModels(test, {"robot.json", from, to}));
  return InputErrorMessage([&] { LoadRobotSpec(*file); });
}

std::string RobotError(const std::filesystem::path& models) {
  return InputErrorMessage([&] { LoadRobot("tester", models); });
}

TEST(RobotSpecTest, LoadsNameHeightAndResolvesPathsFromItsFolder) {
  const std::filesystem::path models = TesterModels("paths");
  const RobotSpec spec = LoadRobotSpec(SpecFile(models));
  const std::filesystem::path dir = models / "robots" / "tester";
  EXPECT_EQ(spec.name, "tester");
  EXPECT_EQ(spec.urdf_file, dir / "tester.urdf");
  EXPECT_EQ(spec.base_height_m, 0.3);
  ASSERT_EQ(spec.kick_motion_files.size(), 2u);
  EXPECT_EQ(spec.kick_motion_files[0].first, "forward");
  EXPECT_EQ(spec.kick_motion_files[0].second, dir / "motions" / "forward.json");
  EXPECT_EQ(spec.kick_motion_files[1].first, "side");
  EXPECT_EQ(spec.kick_motion_files[1].second, dir / "motions" / "side.json");
}

TEST(RobotSpecTest, ConvertsDegreesOnce) {
  const RobotSpec spec = LoadRobotSpec(SpecFile(TesterModels("degrees")));
  ASSERT_EQ(spec.standing_pose_rad.size(), 2u);  // sorted by joint name
  EXPECT_EQ(spec.standing_pose_rad[0].first, "HipPitch");
  EXPECT_DOUBLE_EQ(spec.standing_pose_rad[0].second, -20.0 * kDegToRad);
  EXPECT_EQ(spec.standing_pose_rad[1].first, "KneePitch");
  EXPECT_DOUBLE_EQ(spec.standing_pose_rad[1].second, 40.0 * kDegToRad);
  EXPECT_EQ(spec.variation.placement_sigma_x_m, 0.01);
  EXPECT_EQ(spec.variation.placement_sigma_y_m, 0.02);
  EXPECT_DOUBLE_EQ(spec.variation.placement_sigma_theta_rad, 2.0 * kDegToRad);
  EXPECT_EQ(spec.variation.motion_speed_sigma_rel, 0.05);
}

// A kick's launch target: a floor and an optional ceiling above it; kicks without one have none.
TEST(RobotSpecTest, LaunchTargetsAreReadAndChecked) {
  const std::string forward = R"({"name": "forward", "motion": "motions/forward.json")";
  const RobotSpec spec = LoadRobotSpec(SpecFile(TesterModels(
      "targets",
      {"robot.json", forward, forward + R"(, "launch_min_mps": 1.0, "launch_max_mps": 1.2)"})));
  ASSERT_EQ(spec.launch_targets.size(), 1u);
  EXPECT_EQ(spec.launch_targets[0].first, "forward");
  EXPECT_EQ(spec.launch_targets[0].second.min_mps, 1.0);
  EXPECT_EQ(spec.launch_targets[0].second.max_mps, 1.2);
  const RobotSpec floor_only = LoadRobotSpec(SpecFile(TesterModels(
      "target_floor", {"robot.json", forward, forward + R"(, "launch_min_mps": 1.5)"})));
  ASSERT_EQ(floor_only.launch_targets.size(), 1u);
  EXPECT_FALSE(floor_only.launch_targets[0].second.max_mps.has_value());
  std::filesystem::path file;
  const std::string inverted = SpecError(
      "target_inverted", forward, forward + R"(, "launch_min_mps": 1.2, "launch_max_mps": 1.0)",
      &file);
  EXPECT_EQ(inverted, file.string() +
                          ": kicks[0].launch_max_mps: must be above launch_min_mps and at most "
                          "50, got 1");
  const std::string zero =
      SpecError("target_zero", forward, forward + R"(, "launch_min_mps": 0)", &file);
  EXPECT_EQ(zero, file.string() + ": kicks[0].launch_min_mps: must be in (0, 50], got 0");
  const std::string ceiling_only =
      SpecError("target_ceiling_only", forward, forward + R"(, "launch_max_mps": 1.0)", &file);
  EXPECT_EQ(ceiling_only, file.string() + ": kicks[0].launch_max_mps: needs launch_min_mps");
}

TEST(RobotSpecTest, BaseHeightMustBePositive) {
  std::filesystem::path file;
  const std::string message =
      SpecError("zero_height", "\"base_height_m\": 0.3", "\"base_height_m\": 0", &file);
  EXPECT_EQ(message, file.string() + ": base_height_m: must be > 0, got 0");
}

TEST(RobotSpecTest, BaseHeightHasARange) {
  std::filesystem::path file;
  const std::string message =
      SpecError("huge_height", "\"base_height_m\": 0.3", "\"base_height_m\": 1e308", &file);
  EXPECT_EQ(message, file.string() + ": base_height_m: must be in [0, 10], got 1e+308");
}

// A URDF that is a device or a FIFO: one line, before anything is opened (a FIFO would block,
// /dev/zero would be read until memory runs out).
TEST(RobotSpecTest, AUrdfThatIsNotARegularFileIsRefused) {
  const std::filesystem::path fifo_models = TesterModels("urdf_fifo");
  const std::filesystem::path fifo = fifo_models / "robots" / "tester" / "pipe.urdf";
  std::filesystem::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& urdf : {std::string("/dev/zero"), fifo.string()}) {
    const std::filesystem::path models = TesterModels(
        "urdf_device", {"robot.json", "\"urdf\": \"tester.urdf\"", "\"urdf\": \"" + urdf + "\""});
    EXPECT_EQ(RobotError(models),
              (models / "robots" / "tester" / "robot.json").string() + ": urdf: refers to " + urdf +
                  ", which is not a regular file (a device or a pipe?)");
  }
}

TEST(RobotSpecTest, NegativePlacementSigmaIsRejected) {
  std::filesystem::path file;
  const std::string message = SpecError("negative_sigma", "\"placement_sigma_y_m\": 0.02",
                                        "\"placement_sigma_y_m\": -0.02", &file);
  EXPECT_EQ(message,
            file.string() + ": trial_variation.placement_sigma_y_m: must be >= 0, got -0.02");
}

TEST(RobotSpecTest, NegativeHeadingSigmaIsReportedInDegrees) {
  std::filesystem::path file;
  const std::string message = SpecError("negative_theta", "\"placement_sigma_theta_deg\": 2.0",
                                        "\"placement_sigma_theta_deg\": -2.5", &file);
  EXPECT_EQ(message,
            file.string() + ": trial_variation.placement_sigma_theta_deg: must be >= 0, got -2.5");
}

TEST(RobotSpecTest, MotionSpeedSigmaMustStayBelowOneHalf) {
  std::filesystem::path file;
  const std::string message = SpecError("speed_sigma", "\"motion_speed_sigma_rel\": 0.05",
                                        "\"motion_speed_sigma_rel\": 0.5", &file);
  EXPECT_EQ(message,
            file.string() + ": trial_variation.motion_speed_sigma_rel: must be < 0.5, got 0.5");
}

TEST(RobotSpecTest, DuplicateKickNameIsRejected) {
  std::filesystem::path file;
  const std::string message =
      SpecError("duplicate_kick", "\"name\": \"side\"", "\"name\": \"forward\"", &file);
  EXPECT_EQ(message, file.string() + ": kicks[1].name: duplicate 'forward'");
}

TEST(RobotSpecTest, EmptyKickNameIsRejected) {
  std::filesystem::path file;
  const std::string message =
      SpecError("empty_kick", "\"name\": \"side\"", "\"name\": \"\"", &file);
  EXPECT_EQ(message, file.string() + ": kicks[1].name: must not be empty");
}

TEST(RobotSpecTest, RobotWithoutKicksIsRejected) {
  std::filesystem::path file;
  const std::string message = SpecError("no_kicks", R"([
    {"name": "forward", "motion": "motions/forward.json"},
    {"name": "side", "motion": "motions/side.json"}
  ])",
                                        "[]", &file);
  EXPECT_EQ(message, file.string() + ": kicks: must list at least one kick");
}

TEST(RobotSpecTest, UnknownVariationFieldIsRejected) {
  std::filesystem::path file;
  const std::string message =
      SpecError("typo", "\"placement_sigma_x_m\"", "\"placement_sigma_m\"", &file);
  EXPECT_EQ(message, file.string() + ": trial_variation.placement_sigma_m: unknown field");
}

TEST(RobotSpecTest, StandingPoseValuesMustBeNumbers) {
  std::filesystem::path file;
  const std::string message =
      SpecError("pose_type", "\"KneePitch\": 40.0", "\"KneePitch\": \"bent\"", &file);
  EXPECT_EQ(message,
            file.string() + ": standing_pose_deg.KneePitch: must be a number, got \"bent\"");
}

TEST(RobotSpecTest, MissingTrialVariationIsNamed) {
  std::filesystem::path file;
  const std::string message = SpecError("no_variation", R"(,
  "trial_variation": {
    "placement_sigma_x_m": 0.01,
    "placement_sigma_y_m": 0.02,
    "placement_sigma_theta_deg": 2.0,
    "motion_speed_sigma_rel": 0.05
  })",
                                        "", &file);
  EXPECT_EQ(message, file.string() + ": trial_variation: missing");
}

TEST(RobotSpecTest, LoadRobotAssemblesSpecModelAndMotions) {
  const Robot robot = LoadRobot("tester", TesterModels("assemble"));
  EXPECT_EQ(robot.spec.name, "tester");
  EXPECT_EQ(robot.model.name, "tester");
  EXPECT_EQ(robot.model.joints.size(), 3u);
  ASSERT_EQ(robot.motions.size(), 2u);
  EXPECT_EQ(robot.motions[0].name, "forward");
  EXPECT_EQ(robot.motions[1].name, "side");
  EXPECT_EQ(robot.FindMotion("forward"), 0);
  EXPECT_EQ(robot.FindMotion("side"), 1);
  EXPECT_EQ(robot.FindMotion("Side"), std::nullopt);
}

TEST(RobotSpecTest, MotionFasterThanAJointCanTurnIsRejected) {
  // Knee 40 -> 100 deg in 0.1 s: the spline's peak is 1.5 * 60 deg / 0.1 s = 15.7 rad/s, and a
  // trial may play it 1.15 times as fast; the URDF allows 6 rad/s.
  const std::filesystem::path models = TesterModels(
      "too_fast", {"motions/forward.json", "\"time_s\": 0.35", "\"time_s\": 0.1"});
  const std::string message = RobotError(models);
  EXPECT_THAT(message, StartsWith((models / "robots/tester/motions/forward.json").string() +
                                  ": keyframes: KneePitch must turn at 18."));
  EXPECT_THAT(message, HasSubstr("when played 1.15 times as fast (the fastest trial), over its "
                                 "limit of 6.000 rad/s"));
}

TEST(RobotSpecTest, ShippedMotionsRespectTheJointSpeedLimits) {
  for (const char* name : {"nao", "aibo_ers7"}) {
    const Robot robot = LoadRobot(name, ModelsDir());  // throws if a motion is too fast
    EXPECT_FALSE(robot.motions.empty()) << name;
  }
}

TEST(RobotSpecTest, StandingPositionsFollowTheModelsJointOrder) {
  const Robot robot = LoadRobot("tester", TesterModels("standing"));
  // Joints in model order: HipPitch, KneePitch, SoleFixed (fixed, not named: 0).
  const std::vector<double> expected = {-20.0 * kDegToRad, 40.0 * kDegToRad, 0.0};
  EXPECT_EQ(robot.StandingPositions(), expected);
}

// A kick with its own stance starts from it: its joints replace the standing pose, its height
// the robot's; a kick without one starts from robot.json's stance.
TEST(RobotSpecTest, AKicksOwnStanceReplacesTheStandingPoseAndHeight) {
  const Robot robot = LoadRobot(
      "tester", TesterModels("own_stance", {"motions/side.json", R"("name": "side",)",
                                            R"("name": "side", "stance": {"base_height_m": 0.41,
                                               "pose_deg": {"KneePitch": 10.0}},)"}));
  const KickMotion& side = robot.motions[*robot.FindMotion("side")];
  const KickMotion& forward = robot.motions[*robot.FindMotion("forward")];
  const std::vector<double> expected = {-20.0 * kDegToRad, 10.0 * kDegToRad, 0.0};
  EXPECT_EQ(robot.StandingPositions(side), expected);
  EXPECT_EQ(robot.BaseHeightM(side), 0.41);
  EXPECT_EQ(robot.StandingPositions(forward), robot.StandingPositions());
  EXPECT_EQ(robot.BaseHeightM(forward), 0.3);
}

TEST(RobotSpecTest, AStanceJointMustExistAndLieWithinItsLimits) {
  const std::filesystem::path unknown = TesterModels(
      "stance_unknown_joint",
      {"motions/side.json", R"("name": "side",)",
       R"("name": "side", "stance": {"base_height_m": 0.3, "pose_deg": {"Tail": 1.0}},)"});
  const std::filesystem::path motion = unknown / "robots" / "tester" / "motions" / "side.json";
  EXPECT_THAT(RobotError(unknown),
              StartsWith(motion.string() + ": stance.pose_deg.Tail: 'Tail' is not a joint of "));
  const std::filesystem::path beyond = TesterModels(
      "stance_beyond_limit",
      {"motions/side.json", R"("name": "side",)",
       R"("name": "side", "stance": {"base_height_m": 0.3, "pose_deg": {"KneePitch": 130.0}},)"});
  EXPECT_THAT(RobotError(beyond),
              StartsWith((beyond / "robots" / "tester" / "motions" / "side.json").string() +
                         ": stance.pose_deg.KneePitch: 130 deg is outside the joint's limits"));
}

TEST(RobotSpecTest, ABalanceJointMustExistAndItsShiftedStanceLieWithinItsLimits) {
  const std::filesystem::path unknown = TesterModels(
      "balance_unknown_joint",
      {"motions/side.json", R"("name": "side",)",
       R"("name": "side", "balance": {"shift_s": 1, "settle_s": 0, "offsets_deg": {"Tail": 1}},)"});
  EXPECT_THAT(RobotError(unknown),
              StartsWith((unknown / "robots" / "tester" / "motions" / "side.json").string() +
                         ": balance.offsets_deg.Tail: 'Tail' is not a joint of "));
  const std::filesystem::path beyond = TesterModels(
      "balance_beyond_limit",
      {"motions/side.json", R"("name": "side",)",
       R"("name": "side", "balance": {"shift_s": 1, "settle_s": 0,
                                        "offsets_deg": {"HipPitch": 60.0}},)"});
  EXPECT_THAT(RobotError(beyond),
              StartsWith((beyond / "robots" / "tester" / "motions" / "side.json").string() +
                         ": balance.offsets_deg.HipPitch (with the stance): "));
}

TEST(RobotSpecTest, SupportJointsMustBeRevoluteJointsOfTheModel) {
  const std::filesystem::path models = TesterModels(
      "support_joints",
      {"robot.json", R"("name": "tester",)", R"("name": "tester", "support_joints": ["SoleFixed"],)"});
  EXPECT_THAT(RobotError(models),
              StartsWith(SpecFile(models).string() +
                         ": support_joints[0]: 'SoleFixed' is a fixed joint in "));
}

TEST(RobotSpecTest, UnknownRobotListsTheAvailableOnes) {
  const std::filesystem::path models = TesterModels("unknown_robot");
  EXPECT_EQ(InputErrorMessage([&] { LoadRobot("robonova", models); }),
            "no robot 'robonova' in " + (models / "robots").string() + " (available: tester)");
}

TEST(RobotSpecTest, SpecNameMustMatchItsFolder) {
  const std::filesystem::path models =
      TesterModels("name_mismatch", {"robot.json", "\"name\": \"tester\"", "\"name\": \"other\""});
  EXPECT_EQ(RobotError(models), SpecFile(models).string() +
                                    ": name: must be 'tester' (the robot's folder), got 'other'");
}

TEST(RobotSpecTest, StandingPoseJointMustExistInTheUrdf) {
  const std::filesystem::path models = TesterModels(
      "pose_unknown_joint", {"robot.json", "\"KneePitch\": 40.0", "\"AnklePitch\": 40.0"});
  EXPECT_EQ(RobotError(models),
            SpecFile(models).string() + ": standing_pose_deg.AnklePitch: 'AnklePitch' is not a " +
                "joint of " + (models / "robots" / "tester" / "tester.urdf").string());
}

TEST(RobotSpecTest, StandingPoseCannotMoveAFixedJoint) {
  const std::filesystem::path models =
      TesterModels("pose_fixed_joint", {"robot.json", "\"KneePitch\": 40.0", "\"SoleFixed\": 0.0"});
  EXPECT_THAT(RobotError(models),
              StartsWith(SpecFile(models).string() +
                         ": standing_pose_deg.SoleFixed: 'SoleFixed' is a fixed joint in "));
}

TEST(RobotSpecTest, StandingPoseMustLieWithinTheLimits) {
  const std::filesystem::path models = TesterModels(
      "pose_beyond_limit", {"robot.json", "\"HipPitch\": -20.0", "\"HipPitch\": 45.0"});
  const std::string message = RobotError(models);
  EXPECT_THAT(message, StartsWith(SpecFile(models).string() +
                                  ": standing_pose_deg.HipPitch: 45 deg is outside the joint's "
                                  "limits [-85.9"));
  EXPECT_THAT(message, HasSubstr(", 28.6"));
  EXPECT_THAT(message, HasSubstr("] deg"));
}

TEST(RobotSpecTest, MotionJointMustExistInTheUrdf) {
  const std::filesystem::path models =
      TesterModels("motion_unknown_joint", {"motions/side.json", "[\"HipPitch\"]", "[\"Tail\"]"});
  const std::filesystem::path motion = models / "robots" / "tester" / "motions" / "side.json";
  EXPECT_THAT(RobotError(models),
              StartsWith(motion.string() + ": joints[0]: 'Tail' is not a joint of "));
}

TEST(RobotSpecTest, KeyframeBeyondALimitNamesFileKeyframeJointValueAndLimits) {
  const std::filesystem::path models = TesterModels(
      "motion_beyond_limit", {"motions/forward.json", "[100.0, -60.0]", "[130.0, -60.0]"});
  const std::filesystem::path motion = models / "robots" / "tester" / "motions" / "forward.json";
  EXPECT_EQ(RobotError(models),
            motion.string() +
                ": keyframes[1].positions_deg[0] (KneePitch): 130 deg is outside the joint's "
                "limits [0, " +
                FormatNumber(2.0 * kRadToDeg) + "] deg");
}

TEST(RobotSpecTest, BrokenUrdfFailsTheRobot) {
  const std::filesystem::path models =
      TesterModels("broken_urdf",
                   {"tester.urdf", R"(<limit lower="0" upper="2" effort="1" velocity="6"/>)", ""});
  EXPECT_EQ(RobotError(models), (models / "robots" / "tester" / "tester.urdf").string() +
                                    ": joint KneePitch: revolute joint has no <limit>");
}

TEST(RobotSpecTest, MotionMustCarryItsKicksName) {
  const std::filesystem::path models = TesterModels(
      "motion_name", {"motions/side.json", "\"name\": \"side\"", "\"name\": \"forward\""});
  const std::filesystem::path motion = models / "robots" / "tester" / "motions" / "side.json";
  EXPECT_EQ(RobotError(models),
            motion.string() + ": name: must be 'side' (the kick of robot 'tester'), got 'forward'");
}

TEST(RobotSpecTest, NotesAreNotAJointOfTheStandingPose) {
  const std::filesystem::path models = TesterModels(
      "pose_notes",
      {"robot.json", "\"KneePitch\": 40.0", "\"notes\": \"bent knees\", \"KneePitch\": 40.0"});
  EXPECT_EQ(LoadRobotSpec(SpecFile(models)).standing_pose_rad.size(), 2u);
}

// A file robot.json names that does not exist is reported against robot.json's field.
TEST(RobotSpecTest, MissingMotionFileIsNamedWithTheFieldThatNamesIt) {
  const std::filesystem::path models =
      TesterModels("missing_motion", {"robot.json", "motions/side.json", "motions/no_such.json"});
  const std::filesystem::path robot = models / "robots" / "tester";
  EXPECT_THAT(RobotError(models),
              ::testing::MatchesRegex(".*robot\\.json: kicks\\[[0-9]\\]\\.motion: refers to .*"
                                      "motions/no_such\\.json, which does not exist"));
  EXPECT_THAT(RobotError(models), ::testing::StartsWith((robot / "robot.json").string()));
}

TEST(RobotSpecTest, MissingUrdfIsNamedWithTheFieldThatNamesIt) {
  const std::filesystem::path models =
      TesterModels("missing_urdf", {"robot.json", "\"tester.urdf\"", "\"gone.urdf\""});
  const std::filesystem::path robot = models / "robots" / "tester";
  EXPECT_EQ(RobotError(models), (robot / "robot.json").string() + ": urdf: refers to " +
                                    (robot / "gone.urdf").string() + ", which does not exist");
}

// The shipped robots: each loads with its body and kick motions that fit its joints (the NAO's
// fourth, `forward_long`, is the strong kick of issue 12).
TEST(RobotSpecTest, ShippedNaoLoadsWithFourKicks) {
  const Robot nao = LoadRobot("nao", ModelsDir());
  EXPECT_EQ(nao.model.links.size(), 25u);
  EXPECT_EQ(nao.motions.size(), 4u);
  EXPECT_TRUE(nao.FindMotion("forward_long").has_value());
  EXPECT_EQ(nao.StandingPositions().size(), nao.model.joints.size());
  for (const auto& [kick, file] : nao.spec.kick_motion_files) {
    EXPECT_TRUE(nao.FindMotion(kick).has_value()) << kick;
  }
}

TEST(RobotSpecTest, ShippedAiboLoadsWithSixKicks) {
  const Robot aibo = LoadRobot("aibo_ers7", ModelsDir());
  EXPECT_EQ(aibo.model.links.size(), 16u);
  EXPECT_EQ(aibo.motions.size(), 6u);
  EXPECT_TRUE(aibo.FindMotion("forward_short").has_value());
  // The pass and then the power kick, appended last so no other kick's random streams move,
  // stand up for their kicks; the power kick shifts its weight on a floating base.
  EXPECT_EQ(aibo.FindMotion("pass"), 4);
  EXPECT_TRUE(aibo.motions[4].stance.IsOwn());
  EXPECT_EQ(aibo.FindMotion("power"), 5);
  EXPECT_TRUE(aibo.motions[5].stance.IsOwn());
  EXPECT_TRUE(aibo.motions[5].balance.Has());
  EXPECT_EQ(aibo.StandingPositions().size(), aibo.model.joints.size());
}

}  // namespace
}  // namespace foresight
