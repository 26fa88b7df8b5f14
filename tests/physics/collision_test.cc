// Fast balls against posts, nets and obstacle robots: nothing passes through, and a ball rolled
// between the posts counts as a goal and stays in the goal.
#include <gtest/gtest.h>

#include <cmath>

#include "common/geometry.h"
#include "physics/robot_kinematics.h"
#include "physics/trial.h"
#include "tests/support/physics_test_scenes.h"

namespace foresight {
namespace {

constexpr double kFastMps = 10.0;
constexpr double kPenetrationToleranceM = 0.01;

TrialResult Roll(const PhysicsScene& scene, const Vec2& start, double speed_mps,
                 double heading_deg) {
  const double r = scene.field->ball.radius_m;
  return RunRollTrial(scene, RollingBall(start, r, speed_mps, heading_deg * kDegToRad), 7, true);
}

class CollisionTest : public ::testing::Test {
 protected:
  std::unique_ptr<testing::PhysicsFixtureData> data_ = testing::LoadPhysicsFixture("spl", true);
  PhysicsScene scene_ = testing::SceneOf(*data_);
  const GoalSpec& goal_ = data_->field.goal;
  double r_ = data_->field.ball.radius_m;
};

TEST_F(CollisionTest, FastBallBouncesOffAPostWithoutPassingThrough) {
  const Vec2 post(goal_.post_centre_x_m, goal_.post_centre_y_m);
  const TrialResult result = Roll(scene_, Vec2(2.5, post.y()), kFastMps, 0.0);
  ASSERT_FALSE(result.trace.empty());
  for (const TracePoint& p : result.trace) {
    if (p.p_F.z() > goal_.net_height_m) continue;
    const double distance = (p.p_F.head<2>() - post).norm();
    ASSERT_GT(distance, goal_.post_radius_m + r_ - kPenetrationToleranceM) << "t = " << p.t_s;
  }
  EXPECT_EQ(result.outcome.first_contact, Contact::kPost);
  EXPECT_LT(result.outcome.p_F_rest.x(), post.x());  // it bounced back
}

TEST_F(CollisionTest, FastBallIntoTheGoalStopsAtTheBackNet) {
  const double back_x = goal_.post_centre_x_m + goal_.net_depth_m;
  const TrialResult result = Roll(scene_, Vec2(3.0, 0.1), kFastMps, 0.0);
  for (const TracePoint& p : result.trace) {
    ASSERT_LT(p.p_F.x(), back_x - r_ + kPenetrationToleranceM) << "t = " << p.t_s;
  }
  EXPECT_EQ(result.outcome.category, Category::kOppGoal);
  EXPECT_EQ(result.outcome.first_contact, Contact::kNet);
}

TEST_F(CollisionTest, FastBallFromOutsideStopsAtTheSideNet) {
  const double x_mid = goal_.post_centre_x_m + 0.5 * goal_.net_depth_m;
  const double outer_y = goal_.post_centre_y_m + data_->params.materials.net_thickness_m;
  const TrialResult result = Roll(scene_, Vec2(x_mid, 2.5), kFastMps, -90.0);
  for (const TracePoint& p : result.trace) {
    ASSERT_GT(p.p_F.y(), outer_y + r_ - kPenetrationToleranceM) << "t = " << p.t_s;
  }
  EXPECT_EQ(result.outcome.first_contact, Contact::kNet);
  EXPECT_EQ(result.outcome.category, Category::kOut);
}

TEST_F(CollisionTest, BallRolledBetweenThePostsIsAGoalAndStaysInTheGoal) {
  for (double y : {-0.5, 0.0, 0.4}) {
    const TrialResult result = Roll(scene_, Vec2(3.0, y), 2.5, 0.0);
    ASSERT_TRUE(result.settled);
    EXPECT_EQ(result.outcome.category, Category::kOppGoal) << "y = " << y;
    const Vec2 rest = result.outcome.p_F_rest;
    EXPECT_GT(rest.x(), goal_.post_centre_x_m) << "y = " << y;
    EXPECT_LT(rest.x(), goal_.post_centre_x_m + goal_.net_depth_m) << "y = " << y;
    EXPECT_LT(std::abs(rest.y()), goal_.post_centre_y_m) << "y = " << y;
  }
}

TEST_F(CollisionTest, OwnGoalAndSideLineAreClassifiedByTheFirstLineCrossed) {
  EXPECT_EQ(Roll(scene_, Vec2(-3.0, 0.2), 3.0, 180.0).outcome.category, Category::kOwnGoal);
  EXPECT_EQ(Roll(scene_, Vec2(0.0, 2.0), 3.0, 90.0).outcome.category, Category::kOut);
  // Over the goal line beside the goal: out, although it ends near the goal.
  EXPECT_EQ(Roll(scene_, Vec2(3.5, 1.5), 3.0, 0.0).outcome.category, Category::kOut);
}

}  // namespace
}  // namespace foresight

namespace foresight {
namespace {

TEST(ObstacleCollisionTest, FastBallNeverPassesThroughAStandingRobotsLegs) {
  const auto data = testing::LoadPhysicsFixture("spl", true, "nao");
  const Vec2 robot(1.0, 0.0);
  const double r = data->field.ball.radius_m;
  for (double offset_y : {0.0, 0.05, -0.05}) {
    const Vec2 start(-1.0, offset_y);
    const PhysicsScene scene = testing::SceneOf(*data, {{robot, 0.15}}, start);
    // The obstacle faces the ball: its shins stand across the ball's path.
    const Pose2& pose = scene.obstacle_poses.at(0);
    const RobotModel& model = data->robot->model;
    const std::vector<Eigen::Isometry3d> links = LinkPoses(model, scene.standing_q_rad);
    std::vector<Vec2> shins;
    for (const char* name : {"l_tibia", "r_tibia"}) {
      const Eigen::Vector3d p = links[*model.FindLink(name)].translation();
      shins.push_back(pose.ToField(Vec2(p.x(), p.y())));
    }
    const TrialResult result = Roll(scene, start, kFastMps, 0.0);
    for (const TracePoint& p : result.trace) {
      for (const Vec2& shin : shins) {
        // A shin is a box about 7 cm wide: the ball's centre stays a radius plus 2 cm away.
        ASSERT_GT((p.p_F.head<2>() - shin).norm(), r + 0.02)
            << "offset " << offset_y << ", t = " << p.t_s;
      }
    }
    EXPECT_EQ(result.outcome.first_contact, Contact::kObstacle) << "offset " << offset_y;
    // A ball that hits the rounded toe can fly up and over the robot (a real toe does that
    // too); it may cross the robot's line only in the air, never along the carpet.
    for (std::size_t i = 1; i < result.trace.size(); ++i) {
      const Eigen::Vector3d& a = result.trace[i - 1].p_F;
      const Eigen::Vector3d& b = result.trace[i].p_F;
      if ((a.x() < robot.x()) != (b.x() < robot.x()) && std::abs(b.y() - robot.y()) < 0.15) {
        EXPECT_GT(b.z(), 0.3) << "offset " << offset_y << ", t = " << result.trace[i].t_s;
      }
    }
  }
}

}  // namespace
}  // namespace foresight

namespace foresight {
namespace {

// Issue 12: a ball that flies over the crossbar crosses the goal line between the posts but is
// out; a ball rolling off the carpet stops at its edge instead of rolling on for tens of metres.
TEST_F(CollisionTest, BallOverTheCrossbarIsOut) {
  BallState lob = RollingBall(Vec2(3.8, 0.0), r_, 2.0, 0.0);
  lob.v_F.z() = 4.5;  // at the goal line (0.4 s later) its centre is about 1 m up; the bar 0.8 m
  const TrialResult result = RunRollTrial(scene_, lob, 7, true);
  bool over_the_line_high = false;
  for (const TracePoint& p : result.trace) {
    if (std::abs(p.p_F.x() - goal_.post_centre_x_m) < 0.05) over_the_line_high = p.p_F.z() > 0.8;
  }
  EXPECT_TRUE(over_the_line_high);
  EXPECT_EQ(result.outcome.category, Category::kOut);
}

TEST_F(CollisionTest, TheCarpetsEdgeStopsARollingBall) {
  const TrialResult result = Roll(scene_, Vec2(0.0, 2.0), 4.0, 90.0);
  EXPECT_TRUE(result.settled);
  EXPECT_EQ(result.outcome.category, Category::kOut);
  EXPECT_NEAR(result.outcome.p_F_rest.y(), 0.5 * data_->field.carpet_width_m, 0.05);
  EXPECT_LT(result.outcome.time_s, 1.0);  // 1.7 m at about 4 m/s, not the 15 s of a 30 m roll
}

}  // namespace
}  // namespace foresight
