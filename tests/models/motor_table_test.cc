#include "models/motor_table.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "models/robot_spec.h"
#include "tests/support/model_test_util.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

using testing::InputErrorMessage;
using testing::ModelsDir;

constexpr MotorLine kLine{8.0, 4.0};

TEST(MotorLineTest, DrivingTorqueFallsOnTheLineAndBrakingIsCappedAtStall) {
  const auto at = [](double speed) { return kLine.TorqueRangeNm(speed); };
  EXPECT_DOUBLE_EQ(at(0.0).max_nm, 8.0);
  EXPECT_DOUBLE_EQ(at(0.0).min_nm, -8.0);
  EXPECT_DOUBLE_EQ(at(1.0).max_nm, 6.0);    // 8 (1 - 1/4)
  EXPECT_DOUBLE_EQ(at(1.0).min_nm, -8.0);   // braking a forward turn
  EXPECT_DOUBLE_EQ(at(-3.0).min_nm, -2.0);  // 8 (1 - 3/4) backwards
  EXPECT_DOUBLE_EQ(at(-3.0).max_nm, 8.0);
  EXPECT_DOUBLE_EQ(at(4.0).max_nm, 0.0);  // no-load speed: nothing left to drive with
  EXPECT_DOUBLE_EQ(at(5.0).max_nm, 0.0);  // pushed beyond it: still nothing, never negative
  EXPECT_DOUBLE_EQ(at(5.0).min_nm, -8.0);
}

// The shipped NAO's motors against Aldebaran's tables, and the URDF's joint speeds against the
// tables' no-load speeds (the URDF models the V3.x tables: robot.json's motors notes).
TEST(MotorTableTest, ShippedNaoMotorsAreTheTablesAndReachTheUrdfSpeeds) {
  const Robot nao = LoadRobot("nao", ModelsDir());
  const auto motor = [&](const char* joint) { return nao.motors[*nao.model.FindJoint(joint)]; };
  EXPECT_NEAR(motor("RHipPitch").stall_torque_nm, 7.78, 0.01);  // type B, 7.78 Nm
  EXPECT_NEAR(motor("RKneePitch").no_load_speed_radps * 180 / 3.14159265358979, 366.83, 0.01);
  EXPECT_NEAR(motor("LHipRoll").stall_torque_nm, 11.97, 0.01);  // type A, 11.97 Nm
  EXPECT_NEAR(motor("LAnkleRoll").no_load_speed_radps * 180 / 3.14159265358979, 238.45, 0.01);
  EXPECT_NEAR(motor("LShoulderPitch").stall_torque_nm, 2.27, 0.01);  // RE-Max 17, type A
  EXPECT_NEAR(motor("HeadPitch").stall_torque_nm, 2.61, 0.01);       // RE-Max 17, type B
  for (std::size_t j = 0; j < nao.model.joints.size(); ++j) {
    const RobotJoint& joint = nao.model.joints[j];
    if (joint.kind != RobotJoint::Kind::kRevolute) continue;
    EXPECT_NEAR(nao.motors[j].no_load_speed_radps / joint.velocity_radps, 1.0, 1e-4) << joint.name;
  }
}

TEST(MotorTableTest, EveryShippedRevoluteJointHasAMotorAtLeastAsFastAsItsLimit) {
  for (const char* name : {"nao", "aibo_ers7"}) {
    const Robot robot = LoadRobot(name, ModelsDir());
    for (std::size_t j = 0; j < robot.model.joints.size(); ++j) {
      const RobotJoint& joint = robot.model.joints[j];
      if (joint.kind != RobotJoint::Kind::kRevolute) continue;
      EXPECT_GT(robot.motors[j].stall_torque_nm, 0.0) << name << " " << joint.name;
      EXPECT_GE(robot.motors[j].no_load_speed_radps, joint.velocity_radps * (1 - 1e-4))
          << name << " " << joint.name;
    }
  }
}

MotorTable Read(const std::string& text) {
  const JsonDocument doc = JsonDocument::Parse(text, "robot.json");
  return ReadMotorTable(doc.Root().Object("motors"));
}

constexpr const char* kTable = R"({"motors": {
  "types": {"B": {"stall_torque_nm": 7.78, "no_load_speed_radps": 6.4025, "source": "table"}},
  "joints": {"RHipPitch": "B"}}})";

TEST(MotorTableTest, ReadsTypesAndJoints) {
  const MotorTable table = Read(kTable);
  ASSERT_EQ(table.size(), 1u);
  EXPECT_EQ(table[0].first, "RHipPitch");
  EXPECT_EQ(table[0].second.stall_torque_nm, 7.78);
  EXPECT_EQ(table[0].second.no_load_speed_radps, 6.4025);
}

TEST(MotorTableTest, BadFiguresAreNamedWithTheirValue) {
  const auto error = [](const std::string& from, const std::string& to) {
    return InputErrorMessage([&] { Read(testing::ReplaceOnce(kTable, from, to)); });
  };
  EXPECT_EQ(error("7.78", "0"), "robot.json: motors.types.B.stall_torque_nm: must be > 0, got 0");
  EXPECT_EQ(error("6.4025", "-1"),
            "robot.json: motors.types.B.no_load_speed_radps: must be > 0, got -1");
  EXPECT_EQ(error("\"table\"", "\"\""),
            "robot.json: motors.types.B.source: must say where the figures come from");
  EXPECT_EQ(error("\"RHipPitch\": \"B\"", "\"RHipPitch\": \"C\""),
            "robot.json: motors.joints.RHipPitch: 'C' is not one of motors.types");
}

TEST(MotorTableTest, JointsWithoutMotorsOrTooSlowMotorsAreRejected) {
  const RobotModel nao = LoadRobotModel(ModelsDir() / "robots/nao/nao.urdf");
  const std::string missing = InputErrorMessage([&] { JointMotors(Read(kTable), nao, "f.json"); });
  EXPECT_EQ(missing,
            "f.json: motors.joints.HeadYaw: missing (every revolute joint needs its motor)");
  const std::string slow = InputErrorMessage(
      [&] { JointMotors(Read(testing::ReplaceOnce(kTable, "6.4025", "6.3")), nao, "f.json"); });
  EXPECT_EQ(slow,
            "f.json: motors.joints.RHipPitch: the motor's no-load speed 6.3 rad/s lies "
            "below the joint's velocity limit 6.40239 rad/s");
  const std::string unknown = InputErrorMessage([&] {
    JointMotors(Read(testing::ReplaceOnce(kTable, "\"RHipPitch\": \"B\"", "\"Tail\": \"B\"")), nao,
                "f.json");
  });
  EXPECT_EQ(unknown, "f.json: motors.joints.Tail: not a revolute joint of " +
                         (ModelsDir() / "robots/nao/nao.urdf").string());
}

}  // namespace
}  // namespace foresight
