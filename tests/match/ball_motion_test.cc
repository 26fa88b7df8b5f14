// The match's ball: a kick through an open field rolls exactly v^2 / 2a in v / a (the coarse
// model replayed in time), and a ball rolling into a robot's body stops one ball radius short of
// it and names that body.
#include "match/ball_motion.h"

#include <gtest/gtest.h>

#include <vector>

#include "match/kick_executor.h"
#include "models/field_spec.h"
#include "planner/ball_roll.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

FieldSpec Field() {
  return LoadFieldSpec(testing::ModelsDir() / "fields" / "four_legged.json");
}

BallRoll Kick(const FieldSpec& field, double speed_mps, double decel, const Vec2& from) {
  const CoarseKickExecutor executor(field, decel);
  ConcreteAction action;
  action.kick_index = 0;
  action.launch_speed_mps = speed_mps;
  const Outcome outcome = executor.Execute({}, DrawnState{Pose2{from, 0.0}, from}, action);
  return *RollFromOutcome(from, outcome, decel);
}

TEST(BallMotionTest, OpenFieldKickRollsVSquaredOverTwoA) {
  const FieldSpec field = Field();
  const double v = 0.9, a = 0.27;
  BallRoll roll = Kick(field, v, a, Vec2(-1.0, 0.3));
  double t = 0.0;
  while (!roll.Done()) {
    EXPECT_FALSE(AdvanceRoll(roll, 0.04, {}).has_value());
    t += 0.04;
    ASSERT_LT(t, 10.0);
  }
  EXPECT_NEAR(roll.Position().x(), -1.0 + StopDistance(v, a), 1e-9);
  EXPECT_NEAR(roll.Position().y(), 0.3, 1e-12);
  EXPECT_NEAR(roll.elapsed_s, v / a, 1e-9);
  EXPECT_NEAR(roll.speed0_mps, v, 1e-9);
}

TEST(BallMotionTest, PositionFollowsConstantDeceleration) {
  const FieldSpec field = Field();
  const double v = 0.6, a = 0.3;
  BallRoll roll = Kick(field, v, a, Vec2(0.0, 0.0));
  AdvanceRoll(roll, 1.0, {});
  EXPECT_NEAR(roll.travelled_m, v * 1.0 - 0.5 * a, 1e-12);
}

TEST(BallMotionTest, BallRollingIntoARobotStopsAtItsBody) {
  const FieldSpec field = Field();
  BallRoll roll = Kick(field, 1.0, 0.27, Vec2(0.0, 0.0));
  const double contact = 0.12 + field.ball.radius_m;
  const std::vector<BodyDisc> bodies = {{Vec2(0.5, 1.0), contact, false},   // off the path
                                        {Vec2(0.8, 0.05), contact, false},  // in it
                                        {Vec2(0.3, 0.0), contact, true}};   // ignored (kicker)
  std::optional<int> hit;
  for (int i = 0; i < 200 && !roll.Done(); ++i) hit = hit ? hit : AdvanceRoll(roll, 0.04, bodies);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(*hit, 1);
  EXPECT_NEAR((roll.Position() - Vec2(0.8, 0.05)).norm(), contact, 1e-9);
  EXPECT_TRUE(roll.Done());
}

}  // namespace
}  // namespace foresight
