// Exact answers of the coarse roll with rebounds and with a launch offset: a head-on
// hit leaves at e times the speed it arrived with, an oblique one is reflected about the contact
// normal, the category is the first line crossed, and the contact count is bounded.
#include <gtest/gtest.h>

#include <cmath>

#include "models/physics_params.h"
#include "planner/ball_roll.h"
#include "planner/coarse_planner.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

class ReboundRollTest : public ::testing::Test {
 protected:
  ReboundRollTest() : situation_(testing::MakeSituation({})) {
    // The shipped materials: the coarse model's one source of its restitution.
    const BallPairs e =
        LoadPhysicsParams(testing::ModelsDir() / "physics" / "spl.json").materials.restitution;
    situation_.evaluation.rebounds = {true, 8, e.post, e.net, e.robot};
    world_ = CoarseWorld::Build(MakeScene(situation_));
  }

  Outcome Roll(Vec2 start, double heading_deg, double speed, double offset = 0.0) const {
    return RollBall(world_, start, UnitVector(heading_deg * kDegToRad), speed, offset);
  }
  double a() const { return world_.deceleration_mps2; }
  double e_post() const { return world_.rebounds.post; }
  Vec2 LeftPost() const {
    return Vec2(situation_.field.goal.post_centre_x_m, situation_.field.goal.post_centre_y_m);
  }
  double PostContact() const {
    return situation_.field.goal.post_radius_m + situation_.field.ball.radius_m;
  }

  Situation situation_;
  CoarseWorld world_;
};

TEST_F(ReboundRollTest, TheShippedPostRestitutionIsRead) {
  EXPECT_DOUBLE_EQ(e_post(), 0.3);
  EXPECT_DOUBLE_EQ(world_.rebounds.net, 0.03);
  EXPECT_DOUBLE_EQ(world_.rebounds.robot, 0.18);
}

TEST_F(ReboundRollTest, HeadOnIntoAPostLeavesAtEVAndStopsWhereThatSpeedCarriesIt) {
  const double v = 2.0, run_up = 1.0;
  const Outcome o = Roll(LeftPost() - Vec2(run_up, 0.0), 0.0, v);
  const double s_hit = run_up - PostContact();
  const double v_hit = std::sqrt(v * v - 2.0 * a() * s_hit);
  const double v_out = e_post() * v_hit;
  EXPECT_EQ(o.first_contact, Contact::kPost);
  EXPECT_NEAR(o.p_F_rest.x(), LeftPost().x() - PostContact() - v_out * v_out / (2.0 * a()), 1e-12);
  EXPECT_NEAR(o.p_F_rest.y(), LeftPost().y(), 1e-12);
  EXPECT_NEAR(o.time_s, (v - v_hit) / a() + v_out / a(), 1e-12);
  EXPECT_EQ(o.category, Category::kInfield);
}

TEST_F(ReboundRollTest, AnObliqueHitIsReflectedAboutTheContactNormal) {
  // The path passes the post's centre 6 cm to the side, outside the goal: the contact normal is
  // tilted by asin(b / R) from the path; the normal speed is reversed and scaled by e, the
  // tangential kept, and the ball leaves beside the goal, away from the side net.
  const double v = 2.5, b = 0.06, R = PostContact();
  const Vec2 start = LeftPost() + Vec2(-1.2, b);
  const Outcome o = Roll(start, 0.0, v);
  const double phi = std::asin(b / R);  // between the path and the inward normal
  const Vec2 normal(-std::cos(phi), std::sin(phi)), tangent(std::sin(phi), std::cos(phi));
  const Vec2 hit = LeftPost() + R * normal;
  const double v_hit = std::sqrt(v * v - 2.0 * a() * (hit.x() - start.x()));
  const Vec2 out = e_post() * v_hit * std::cos(phi) * normal + v_hit * std::sin(phi) * tangent;
  const Vec2 expected = hit + out.normalized() * (out.squaredNorm() / (2.0 * a()));
  EXPECT_EQ(o.first_contact, Contact::kPost);
  EXPECT_NEAR(o.p_F_rest.x(), expected.x(), 1e-12);
  EXPECT_NEAR(o.p_F_rest.y(), expected.y(), 1e-12);
  EXPECT_NEAR(o.time_s, (v - v_hit) / a() + out.norm() / a(), 1e-12);
}

TEST_F(ReboundRollTest, AShotOffTheBackNetCountsAsAGoalWhereverItRests) {
  const GoalSpec& g = situation_.field.goal;
  const double v = 5.0;
  const Outcome o = Roll(Vec2(3.0, 0.1), 0.0, v);
  const double x_net = g.post_centre_x_m + g.net_depth_m - situation_.field.ball.radius_m;
  const double v_out = world_.rebounds.net * std::sqrt(v * v - 2.0 * a() * (x_net - 3.0));
  EXPECT_EQ(o.first_contact, Contact::kNet);
  EXPECT_EQ(o.category, Category::kOppGoal);  // the goal line was crossed first
  EXPECT_NEAR(o.p_F_rest.x(), x_net - v_out * v_out / (2.0 * a()), 1e-12);
}

TEST_F(ReboundRollTest, AFastReboundOutOfTheGoalStillCountsTheGoalLineFirst) {
  // A rebound that carries the ball back over the goal line (restitution 1 for the test).
  world_.rebounds.net = 1.0;
  const Outcome o = Roll(Vec2(3.0, 0.1), 0.0, 5.0);
  EXPECT_LT(o.p_F_rest.x(), world_.lines.out_x_m);  // back on the field
  EXPECT_EQ(o.category, Category::kOppGoal);
}

TEST_F(ReboundRollTest, TheContactAfterMaxContactsReboundsStopsTheBall) {
  // Between two robots 2 m apart with restitution 0.9, the ball would bounce to and fro.
  Situation s = situation_;
  s.obstacles = {{Vec2(1.0, 0.0), 0.2}, {Vec2(-1.0, 0.0), 0.2}};
  s.evaluation.rebounds.robot = 0.9;
  s.evaluation.rebounds.max_contacts = 1;
  const CoarseWorld world = CoarseWorld::Build(MakeScene(s));
  const double contact = 1.0 - 0.2 - situation_.field.ball.radius_m;
  const Outcome o = RollBall(world, Vec2(0.0, 0.0), Vec2(1.0, 0.0), 4.0);
  EXPECT_EQ(o.first_contact, Contact::kObstacle);
  EXPECT_NEAR(o.p_F_rest.x(), -contact, 1e-12);  // stopped at the second robot
  s.evaluation.rebounds.max_contacts = 8;
  const Outcome free =
      RollBall(CoarseWorld::Build(MakeScene(s)), Vec2(0.0, 0.0), Vec2(1.0, 0.0), 4.0);
  EXPECT_GT(free.p_F_rest.x(), -contact + 1e-3);  // it rebounded off the second one too
}

TEST_F(ReboundRollTest, WithoutRestitutionAHeadOnHitStopsAtTheContactAsInThePaper) {
  world_.rebounds.post = 0.0;
  const Outcome o = Roll(LeftPost() - Vec2(1.0, 0.0), 0.0, 2.0);
  EXPECT_NEAR(o.p_F_rest.x(), LeftPost().x() - PostContact(), 1e-12);
}

TEST_F(ReboundRollTest, ALaunchOffsetIsCoveredBeforeTheBallDecelerates) {
  const double v = 1.1, offset = 0.05;
  for (bool rebounds : {false, true}) {
    world_.rebounds.enabled = rebounds;
    const Vec2 start(-1.0, 0.3);
    const Outcome o = Roll(start, 30.0, v, offset);
    EXPECT_NEAR((o.p_F_rest - start).norm(), offset + v * v / (2.0 * a()), 1e-12);
    EXPECT_NEAR(o.time_s, offset / v + v / a(), 1e-12);
  }
}

TEST_F(ReboundRollTest, AContactWithinTheOffsetMeetsTheLaunchSpeed) {
  const double v = 1.5, offset = 0.05;
  const Vec2 start = LeftPost() - Vec2(PostContact() + 0.03, 0.0);  // 3 cm short of contact
  const Outcome o = Roll(start, 0.0, v, offset);
  const double v_out = e_post() * v;
  EXPECT_NEAR(o.p_F_rest.x(), LeftPost().x() - PostContact() - v_out * v_out / (2.0 * a()), 1e-12);
  EXPECT_NEAR(o.time_s, 0.03 / v + v_out / a(), 1e-12);
}

}  // namespace
}  // namespace foresight
