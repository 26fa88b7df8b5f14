// The watch for a fall after the launch (physics/fall_watch.h): the support margin's geometry,
// the still stop that fires only on a robot at rest, a robot toppled during the watch counted
// as fallen, and trials whose ball, falls and largest tilt the stop keeps.
#include "physics/fall_watch.h"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "common/geometry.h"
#include "models/kick_model.h"
#include "physics/bullet_convert.h"
#include "physics/bullet_world.h"
#include "physics/carpet.h"
#include "physics/kicking_robot.h"
#include "physics/physics_runs.h"
#include "physics/physics_simulator.h"
#include "tests/support/physics_test_scenes.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

TEST(HullMarginTest, IsTheDistanceToTheNearestEdgeInsideAndNegativeOutside) {
  const std::vector<Eigen::Vector2d> square = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0},
                                               {0.0, 1.0}, {0.5, 0.0}, {0.5, 0.5}};
  EXPECT_NEAR(HullMarginM(square, {0.5, 0.5}), 0.5, 1e-12);
  EXPECT_NEAR(HullMarginM(square, {0.1, 0.6}), 0.1, 1e-12);
  EXPECT_NEAR(HullMarginM(square, {1.5, 0.5}), -0.5, 1e-12);
  const std::vector<Eigen::Vector2d> line = {{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}};
  EXPECT_EQ(HullMarginM(line, {1.0, 1.0}), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(HullMarginM(std::vector<Eigen::Vector2d>{}, {0.0, 0.0}),
            -std::numeric_limits<double>::infinity());
}

// A floating NAO held at the forward kick's stance on a bare carpet.
struct StandingNao {
  std::unique_ptr<testing::PhysicsFixtureData> data =
      testing::LoadPhysicsFixture("spl", true, "nao");
  const KickMotion& motion() const {
    return data->robot->motions[*data->robot->FindMotion("forward")];
  }
  BulletWorld world{
      BulletWorld::Kind::kMultiBody,
      {data->params.steps.solver_iterations, data->params.steps.restitution_threshold_mps}};
  std::unique_ptr<KickingRobot> robot;

  StandingNao() {
    data->params.robot.base = RobotBase::kFloating;
    AddCarpetPlane(world, data->params.materials);
    const Robot& nao = *data->robot;
    robot = std::make_unique<KickingRobot>(
        world, nao, PlanarPose(0.2, -0.1, nao.BaseHeightM(motion()), 0.3),
        nao.StandingPositions(motion()), KickJoints(nao, motion(), RobotBase::kFloating),
        data->params);
    const double dt = data->params.steps.kick_time_step_s;
    for (int step = 0; step < 500; ++step) world.world().stepSimulation(dt, 0, dt);  // 1 s
  }
  btDispatcher& dispatcher() { return *world.world().getDispatcher(); }
  // The watch from t = 0 with the motion already over (its targets held), for `stand_s`.
  WatchEnd Watch(double stand_s) {
    const double end_s = motion().DurationS();
    return WatchForFall(world, *robot, motion(), {end_s, end_s, end_s + stand_s, 1.0}, data->params,
                        0.0);
  }
};

// At rest on both soles it is still; any joint or base speed above the thresholds is not.
TEST(StandsStillTest, HoldsForARobotAtRestAndNotForOneThatMoves) {
  StandingNao nao;
  const WatchParams& watch = nao.data->params.watch;
  EXPECT_GT(SupportMarginM(*nao.robot, nao.dispatcher()), watch.still_support_margin_m);
  EXPECT_TRUE(StandsStill(*nao.robot, nao.dispatcher(), watch));
  btMultiBody& body = nao.robot->body();
  body.setBaseVel(btVector3(0.0, 2.0 * watch.still_base_speed_mps, 0.0));
  EXPECT_FALSE(StandsStill(*nao.robot, nao.dispatcher(), watch));
  body.setBaseVel(btVector3(0.0, 0.0, 0.0));
  body.setBaseOmega(btVector3(2.0 * watch.still_base_rate_radps, 0.0, 0.0));
  EXPECT_FALSE(StandsStill(*nao.robot, nao.dispatcher(), watch));
  body.setBaseOmega(btVector3(0.0, 0.0, 0.0));
  body.setJointVel(0, -2.0 * watch.still_joint_speed_radps);
  EXPECT_FALSE(StandsStill(*nao.robot, nao.dispatcher(), watch));
}

// A robot at rest ends the watch once it has stood still for still_time_s, no sooner.
TEST(FallWatchTest, ARobotAtRestEndsTheWatchAfterItsStillTime) {
  StandingNao nao;
  const WatchParams& watch = nao.data->params.watch;
  const WatchEnd end = nao.Watch(2.0);
  EXPECT_TRUE(end.still);
  EXPECT_FALSE(end.fell);
  const double start_s = nao.motion().DurationS();
  EXPECT_GE(end.t_s - start_s, watch.still_time_s);
  EXPECT_LT(end.t_s - start_s, watch.still_time_s + 3.0 * nao.data->params.steps.kick_time_step_s);
}

// Pushed over during the watch (its torso set moving sideways at 1 m/s), the robot falls, and the
// watch counts it: the still stop never fires on a robot that is moving.
TEST(FallWatchTest, ARobotToppledDuringTheWatchIsCountedAsFallen) {
  StandingNao nao;
  nao.robot->body().setBaseVel(btVector3(0.0, 1.0, 0.0));
  const WatchEnd end = nao.Watch(2.0);
  EXPECT_TRUE(end.fell);
  EXPECT_FALSE(end.still);
  EXPECT_GT(end.max_tilt_rad, nao.data->params.robot.fall_tilt_rad);
}

// A nudge it recovers from: the watch waits until the sway has died out.
TEST(FallWatchTest, ARobotThatSwaysIsWatchedUntilItIsStill) {
  StandingNao nao;
  nao.robot->body().setBaseOmega(btVector3(0.3, 0.0, 0.0));
  const WatchEnd end = nao.Watch(2.0);
  EXPECT_FALSE(end.fell);
  EXPECT_GT(end.max_tilt_rad, 0.0);
  const double start_s = nao.motion().DurationS();
  EXPECT_GT(end.t_s - start_s, nao.data->params.watch.still_time_s + 0.02);
}

// The ball's outcome is fixed at the launch, and up to the still stop the watch steps as the
// full watch does: the AIBO's forward kick (whose robot stands still before its settle time
// ends) gives the same balls bit for bit with the stop as without it, the same falls, a largest
// tilt the rest of the full watch does not raise, and the same bytes on 1 and 2 threads.
TEST(FallWatchTest, TheStillStopKeepsTheBallTheFallsAndTheLargestTilt) {
  auto data = testing::LoadPhysicsFixture("four_legged", false, "aibo_ers7");
  data->params.robot.base = RobotBase::kFloating;
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "aibo_ers7.json");
  KickTrialsRequest request;
  const Vec2 ball(0.4, -0.3);
  request.state = DrawnState{Pose2{ball, -20.0 * kDegToRad}, ball};
  request.kick_index = *kicks.Find("forward");
  request.trials = 3;
  request.seed = 17;
  request.threads = 1;
  const PhysicsSimulator shipped(testing::SceneOf(*data), kicks);
  const std::vector<TrialResult> stopped = RunKickTrials(shipped, request);
  request.threads = 2;
  const std::vector<TrialResult> stopped_2 = RunKickTrials(shipped, request);
  data->params.watch.still_time_s = 10.0;  // longer than any watch: the full watch
  const PhysicsSimulator full_watch(testing::SceneOf(*data), kicks);
  const std::vector<TrialResult> full = RunKickTrials(full_watch, request);
  ASSERT_EQ(stopped.size(), full.size());
  for (std::size_t i = 0; i < stopped.size(); ++i) {
    EXPECT_TRUE(full[i].launched);
    EXPECT_EQ(stopped[i].launch_speed_mps, full[i].launch_speed_mps);
    EXPECT_EQ(stopped[i].launch_direction_rad, full[i].launch_direction_rad);
    EXPECT_EQ(stopped[i].outcome.p_F_rest, full[i].outcome.p_F_rest);
    EXPECT_EQ(stopped[i].outcome.category, full[i].outcome.category);
    EXPECT_EQ(stopped[i].outcome.time_s, full[i].outcome.time_s);
    EXPECT_EQ(stopped[i].fell, full[i].fell);
    EXPECT_LE(stopped[i].max_tilt_rad, full[i].max_tilt_rad);
    EXPECT_NEAR(stopped[i].max_tilt_rad, full[i].max_tilt_rad, 0.01 * kDegToRad);
    EXPECT_EQ(stopped[i].max_tilt_rad, stopped_2[i].max_tilt_rad);
    EXPECT_EQ(stopped[i].outcome.p_F_rest, stopped_2[i].outcome.p_F_rest);
  }
}

}  // namespace
}  // namespace foresight
