// Analytic answers of the coarse ball model: stop distance, contacts one radius short of the
// surface, categories at the edges of lines and goals.
#include "planner/ball_roll.h"

#include <gtest/gtest.h>

#include "planner/coarse_planner.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

class BallRollTest : public ::testing::Test {
 protected:
  BallRollTest()
      : situation_(testing::MakeSituation({})), world_(CoarseWorld::Build(MakeScene(situation_))) {}

  Outcome Roll(Vec2 start, double heading_deg, double speed) const {
    return RollBall(world_, start, UnitVector(heading_deg * kDegToRad), speed);
  }
  double a() const { return situation_.kicks.rolling_deceleration_mps2; }

  Situation situation_;
  CoarseWorld world_;
};

TEST_F(BallRollTest, FreeRollStopsAfterVSquaredOverTwoA) {
  for (double heading : {0.0, 30.0, 45.0, 77.0, -135.0}) {
    const Vec2 start(-1.0, 0.3);
    const double v = 0.9;
    const Outcome o = Roll(start, heading, v);
    const double expected = v * v / (2.0 * a());
    EXPECT_NEAR((o.p_F_rest - start).norm(), expected, 1e-12) << heading;
    EXPECT_NEAR(o.time_s, v / a(), 1e-12);
    EXPECT_EQ(o.first_contact, Contact::kNone);
    EXPECT_EQ(o.category, Category::kInfield);
  }
}

TEST_F(BallRollTest, ZeroOrNegativeSpeedLeavesTheBall) {
  const Outcome o = Roll(Vec2(1.0, 1.0), 0.0, -0.2);
  EXPECT_EQ(o.p_F_rest, Vec2(1.0, 1.0));
  EXPECT_EQ(o.time_s, 0.0);
}

TEST_F(BallRollTest, HitsPostOneBallRadiusShortOfItsSurface) {
  // Straight at the left post of the opponent goal from 1 m in front of it.
  const GoalSpec& g = situation_.field.goal;
  const Vec2 post(g.post_centre_x_m, g.post_centre_y_m);
  const Outcome o = Roll(post - Vec2(1.0, 0.0), 0.0, 3.0);
  EXPECT_EQ(o.first_contact, Contact::kPost);
  EXPECT_NEAR((o.p_F_rest - post).norm(), g.post_radius_m + situation_.field.ball.radius_m, 1e-12);
  EXPECT_NEAR(o.p_F_rest.y(), post.y(), 1e-12);
  EXPECT_EQ(o.category, Category::kInfield);  // stopped before the line
}

TEST_F(BallRollTest, ShotIntoGoalStopsAtBackNetAndCountsAsGoal) {
  const GoalSpec& g = situation_.field.goal;
  const Outcome o = Roll(Vec2(3.0, 0.1), 0.0, 5.0);
  EXPECT_EQ(o.category, Category::kOppGoal);
  EXPECT_EQ(o.first_contact, Contact::kNet);
  EXPECT_NEAR(o.p_F_rest.x(), g.post_centre_x_m + g.net_depth_m - situation_.field.ball.radius_m,
              1e-12);
  EXPECT_NEAR(o.p_F_rest.y(), 0.1, 1e-12);
}

TEST_F(BallRollTest, SideNetFromOutsideStopsTheBall) {
  // Coming from beyond the goal line, across the side net from above (+y) towards -y.
  const GoalSpec& g = situation_.field.goal;
  const double x = g.post_centre_x_m + 0.3;
  const Outcome o = Roll(Vec2(x, 1.5), -90.0, 3.0);
  EXPECT_EQ(o.first_contact, Contact::kNet);
  EXPECT_NEAR(o.p_F_rest.y(), g.post_centre_y_m + situation_.field.ball.radius_m, 1e-12);
  EXPECT_EQ(o.category, Category::kOut);  // it started out there and stays out
}

TEST_F(BallRollTest, ObstacleStopsTheBallOneRadiusShort) {
  Situation s = testing::MakeSituation({}, {{Vec2(1.0, 0.0), 0.2}});
  const CoarseWorld world = CoarseWorld::Build(MakeScene(s));
  const Outcome o = RollBall(world, Vec2(0.0, 0.0), Vec2(1.0, 0.0), 4.0);
  EXPECT_EQ(o.first_contact, Contact::kObstacle);
  EXPECT_NEAR(o.p_F_rest.x(), 1.0 - 0.2 - s.field.ball.radius_m, 1e-12);
  // The time to reach the contact solves s = v t - a t^2 / 2.
  const double t = o.time_s, a = s.kicks.rolling_deceleration_mps2;
  EXPECT_NEAR(4.0 * t - 0.5 * a * t * t, o.p_F_rest.x(), 1e-12);
}

TEST_F(BallRollTest, BallIsOutOnlyWhenCompletelyOverTheSideLine) {
  const FieldSpec& f = situation_.field;
  const double limit = f.HalfWidth() + 0.5 * f.line_width_m + f.ball.radius_m;
  const double v_to = std::sqrt(2.0 * a() * 1.0);  // rolls exactly 1 m
  // Rolls exactly 1 m from 1 m - 1 mm inside the limit: ends 1 mm out.
  EXPECT_EQ(Roll(Vec2(0.0, limit - 0.999), 90.0, v_to).category, Category::kOut);
  EXPECT_EQ(Roll(Vec2(0.0, limit - 1.001), 90.0, v_to).category, Category::kInfield);
  EXPECT_EQ(Roll(Vec2(0.0, -limit + 0.999), -90.0, v_to).category, Category::kOut);
}

TEST_F(BallRollTest, GoalLineBesideTheGoalIsOutAndBetweenThePostsIsAGoal) {
  const FieldSpec& f = situation_.field;
  const double limit_x = f.HalfLength() + 0.5 * f.line_width_m + f.ball.radius_m;
  const double v = std::sqrt(2.0 * a() * 1.0);
  EXPECT_EQ(Roll(Vec2(limit_x - 0.99, 2.0), 0.0, v).category, Category::kOut);
  EXPECT_EQ(Roll(Vec2(limit_x - 0.99, 0.5), 0.0, v).category, Category::kOppGoal);
  EXPECT_EQ(Roll(Vec2(-limit_x + 0.99, -0.5), 180.0, v).category, Category::kOwnGoal);
  EXPECT_EQ(Roll(Vec2(limit_x - 1.01, 0.5), 0.0, v).category, Category::kInfield);
}

TEST_F(BallRollTest, FirstLineCrossedDecides) {
  // Diagonal towards the corner: crosses the side line before the goal line's extension.
  const Outcome o = Roll(Vec2(4.0, 2.9), 30.0, 3.0);
  EXPECT_EQ(o.category, Category::kOut);
}

TEST_F(BallRollTest, BallOnTheNetCanRollAway) {
  // A ball resting against the back net (inside its contact distance) rolls out of the goal.
  const GoalSpec& g = situation_.field.goal;
  const Vec2 start(g.post_centre_x_m + g.net_depth_m - 0.5 * situation_.field.ball.radius_m, 0.0);
  const Outcome o = Roll(start, 180.0, 1.0);
  EXPECT_LT(o.p_F_rest.x(), start.x() - 1.0);
  EXPECT_EQ(o.category, Category::kOppGoal);  // it was in the goal: it counts as scored
}

TEST_F(BallRollTest, BallTouchingAnObstacleCannotPassThroughIt) {
  Situation s = testing::MakeSituation({}, {{Vec2(1.0, 0.0), 0.2}});
  const CoarseWorld world = CoarseWorld::Build(MakeScene(s));
  const Vec2 start(1.0 - 0.2 - 0.5 * s.field.ball.radius_m, 0.0);  // overlapping it
  const Outcome blocked = RollBall(world, start, Vec2(1.0, 0.0), 3.0);
  EXPECT_EQ(blocked.first_contact, Contact::kObstacle);
  EXPECT_EQ(blocked.p_F_rest, start);
  EXPECT_EQ(blocked.time_s, 0.0);
  const Outcome away = RollBall(world, start, Vec2(-1.0, 0.0), 1.0);
  EXPECT_EQ(away.first_contact, Contact::kNone);
}

TEST_F(BallRollTest, BallOutsideTheFieldStaysOutWhenKickedBackIn) {
  const FieldSpec& f = situation_.field;
  const Outcome o = Roll(Vec2(0.0, f.HalfWidth() + 0.2), -90.0, 1.0);
  EXPECT_LT(o.p_F_rest.y(), f.HalfWidth());
  EXPECT_EQ(o.category, Category::kOut);
}

}  // namespace
}  // namespace foresight

namespace foresight {
namespace {

// The roll's kinematics against s(t) = v0 t - a t^2 / 2 and v(t) = v0 - a t at a chosen time.
TEST(BallRollKinematicsTest, SpeedAndTimeAfterARollMatchTheClosedForm) {
  const double v0 = 1.2, a = 0.3, t = 1.5;
  const double s = v0 * t - 0.5 * a * t * t;
  EXPECT_NEAR(SpeedAfterRolling(v0, a, s), v0 - a * t, 1e-12);
  EXPECT_NEAR(TimeToRoll(v0, a, s), t, 1e-12);
  // Beyond the rest distance the ball is at rest, reached at v0 / a.
  EXPECT_EQ(SpeedAfterRolling(v0, a, StopDistance(v0, a) + 1.0), 0.0);
  EXPECT_NEAR(TimeToRoll(v0, a, StopDistance(v0, a) + 1.0), v0 / a, 1e-12);
}

}  // namespace
}  // namespace foresight
