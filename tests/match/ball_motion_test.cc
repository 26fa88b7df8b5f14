// The match's ball: a kick through an open field rolls exactly v^2 / 2a in v / a (the coarse
// model replayed in time); a ball rolling into a robot's body ends its roll one ball radius short
// of it and names that body; the match world then rebounds it with the ball-robot restitution
// (exact speeds head-on and at 45 degrees), and a kick into an adjacent body rebounds.
#include "match/ball_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "match/kick_executor.h"
#include "match/match_world.h"
#include "models/physics_params.h"
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
  const std::vector<BallBody> bodies = {
      {Vec2(0.5, 1.0), Vec2(0.5, 1.0), contact, false},    // off the path
      {Vec2(0.8, 0.05), Vec2(0.8, 0.05), contact, false},  // in it
      {Vec2(0.3, 0.0), Vec2(0.3, 0.0), contact, true}};    // ignored (kicker)
  std::optional<BodyHit> hit;
  for (int i = 0; i < 200 && !roll.Done(); ++i) hit = hit ? hit : AdvanceRoll(roll, 0.04, bodies);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->body, 1);
  EXPECT_NEAR((roll.Position() - Vec2(0.8, 0.05)).norm(), contact, 1e-9);
  EXPECT_NEAR(hit->speed_mps, roll.SpeedAt(roll.travelled_m), 1e-12);
  EXPECT_TRUE(roll.Done());
}

// A world of robots standing at `centres` (facing +x) and a ball rolling from p_F_ball along
// +x at speed_mps; the ball-robot restitution of the four-legged physics file.
struct ReboundWorld {
  FieldSpec field = Field();
  double e = LoadPhysicsParams(testing::ModelsDir() / "physics" / "four_legged.json")
                 .materials.restitution.robot;
  double a = 0.27;
  CoarseWorld static_world;
  MatchWorld world;
  double contact = 0.12 + field.ball.radius_m;

  ReboundWorld(const std::vector<Vec2>& centres, const Vec2& p_F_ball, double speed_mps)
      : static_world(CoarseWorld::Build(Scene{&field, {}, a, CoarseRebounds{}})) {
    for (const Vec2& c : centres) {
      RobotState r;
      r.pose = Pose2{c, 0.0};
      world.robots.push_back(r);
    }
    world.ball.p_F = p_F_ball;
    world.ball.roll = RollFromOutcome(
        p_F_ball, RollBall(static_world, p_F_ball, Vec2(1.0, 0.0), speed_mps), a);
  }
  std::vector<int> Step() {
    return StepBall(world, BallStepParams{contact, 0.04, 0.01, e, &static_world});
  }
};

TEST(BallMotionTest, ABallRollingHeadOnIntoARobotReboundsAtTheRestitutionTimesItsSpeed) {
  const double v0 = 1.0, to_body = 0.3;
  ReboundWorld w({Vec2(to_body + 0.12 + Field().ball.radius_m, 0.0)}, Vec2(0.0, 0.0), v0);
  ASSERT_GT(w.e, 0.0);
  std::vector<int> met;
  for (int i = 0; i < 100 && met.empty(); ++i) met = w.Step();
  ASSERT_EQ(met, std::vector<int>{0});
  ASSERT_TRUE(w.world.ball.roll.has_value());
  const double v_hit = std::sqrt(v0 * v0 - 2.0 * w.a * to_body);
  EXPECT_NEAR(w.world.ball.roll->speed0_mps, w.e * v_hit, 1e-9);
  EXPECT_NEAR(w.world.ball.roll->dir_F.x(), -1.0, 1e-12);
  EXPECT_NEAR(w.world.ball.roll->p_F_start.x(), to_body, 1e-9);
}

TEST(BallMotionTest, AKickIntoAnAdjacentBodyReboundsWithTheBodysRestitution) {
  // The ball lies at the kicker's front and touches a second robot at 45 degrees to the kick:
  // v' = v - (1 + e)(v . n) n gives (v (1 - e) / 2, -v (1 + e) / 2), speed v sqrt((1 + e^2) / 2).
  const double v = 0.8;
  const double contact = 0.12 + Field().ball.radius_m;
  const Vec2 ball(contact, 0.0);
  const Vec2 other = ball + contact * Vec2(std::sqrt(0.5), std::sqrt(0.5));
  ReboundWorld w({Vec2(0.0, 0.0), other}, ball, v);
  w.world.ball.leaving_kicker = 0;
  const std::vector<int> met = w.Step();
  ASSERT_FALSE(met.empty());
  EXPECT_EQ(met.front(), 1);
  ASSERT_TRUE(w.world.ball.roll.has_value());
  EXPECT_NEAR(w.world.ball.roll->speed0_mps, v * std::sqrt((1.0 + w.e * w.e) / 2.0), 1e-9);
  const double f = std::hypot(1.0 - w.e, 1.0 + w.e);
  EXPECT_NEAR(w.world.ball.roll->dir_F.x(), (1.0 - w.e) / f, 1e-9);
  EXPECT_NEAR(w.world.ball.roll->dir_F.y(), -(1.0 + w.e) / f, 1e-9);
  EXPECT_EQ(w.world.ball.leaving_kicker, -1);  // the kicker is a body again
}

TEST(BallMotionTest, ABallJammedBetweenTwoBodiesStops) {
  const double contact = 0.12 + Field().ball.radius_m;
  ReboundWorld w({Vec2(0.0, 0.0), Vec2(2.0 * contact, 0.0)}, Vec2(contact, 0.0), 1.0);
  w.world.ball.leaving_kicker = 0;
  const std::vector<int> met = w.Step();
  // Back and forth, slower each time (e^k), until it is too slow to move or the cap stops it.
  EXPECT_GE(met.size(), 4u);
  EXPECT_LE(static_cast<int>(met.size()), kMaxBodyContactsPerStep);
  EXPECT_FALSE(w.world.ball.roll.has_value());
  EXPECT_NEAR(w.world.ball.p_F.x(), contact, 1e-9);
}

}  // namespace
}  // namespace foresight
