// The weight shift played once (physics/settled_stance.h): the robot ends standing, its torso
// over the support sole, at rest; a fixed base settles nothing.
#include "physics/settled_stance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/geometry.h"
#include "tests/support/physics_test_scenes.h"

namespace foresight {
namespace {

struct ShiftCase {
  const char* kick;
  double side;  // +1: the torso moves to the robot's left (a right-foot kick), -1: to its right
};

class SettledStanceTest : public ::testing::TestWithParam<ShiftCase> {};

TEST_P(SettledStanceTest, TheTorsoStandsOverTheSupportSoleAtRest) {
  const ShiftCase c = GetParam();
  const auto data = testing::LoadPhysicsFixture("spl", true, "nao");
  const Robot& robot = *data->robot;
  const KickMotion& motion = robot.motions[*robot.FindMotion(c.kick)];
  const SettledStance settled = SettleBalance(robot, motion, data->params);
  EXPECT_FALSE(settled.fell);
  EXPECT_LT(settled.max_tilt_rad * kRadToDeg, 5.0);
  // Legs of about 0.20 m turned 16 deg at the hip move the hips 56 mm sideways; the torso's
  // centre of mass (the base frame) goes with them, less what the welded arms and the compliance
  // take (hip and ankle roll of equal size keep both soles level).
  const Eigen::Vector3d shift = settled.state.pose_R0_base.translation();
  EXPECT_GT(c.side * shift.y(), 0.040) << shift.transpose();
  EXPECT_LT(c.side * shift.y(), 0.070) << shift.transpose();
  EXPECT_LT(std::abs(shift.x()), 0.02) << shift.transpose();
  // Nearly at rest after the settle time (the side kicks' larger shift still sways about 1 cm/s):
  // the torso under 2 cm/s, and every joint under 0.1 rad/s, which moves the end of a 0.2 m leg
  // at most as fast (side_kick_right's fastest joint turns at 0.064 rad/s).
  EXPECT_LT(settled.state.v_R0_base.norm(), 0.02);
  for (double qdot : settled.state.qdot_radps) EXPECT_LT(std::abs(qdot), 0.1);
}

INSTANTIATE_TEST_SUITE_P(NaoKicks, SettledStanceTest,
                         ::testing::Values(ShiftCase{"forward", 1.0},
                                           ShiftCase{"forward_long", 1.0},
                                           ShiftCase{"side_kick_right", 1.0},
                                           ShiftCase{"side_kick_left", -1.0}),
                         [](const ::testing::TestParamInfo<ShiftCase>& info) {
                           return std::string(info.param.kick);
                         });

TEST(SettleStancesTest, OnlyAFloatingBaseSettlesAndOnlyMotionsWithABalance) {
  auto data = testing::LoadPhysicsFixture("spl", true, "nao");
  data->params.robot.base = RobotBase::kFixed;
  for (const auto& stance : SettleStances(*data->robot, data->params)) {
    EXPECT_FALSE(stance.has_value());
  }
  data->params.robot.base = RobotBase::kFloating;
  Robot robot = *data->robot;
  robot.motions[0].balance = KickBalance{};  // this one has none
  const SettledStances stances = SettleStances(robot, data->params);
  ASSERT_EQ(stances.size(), robot.motions.size());
  EXPECT_FALSE(stances[0].has_value());
  for (std::size_t m = 1; m < stances.size(); ++m) EXPECT_TRUE(stances[m].has_value());
}

}  // namespace
}  // namespace foresight
