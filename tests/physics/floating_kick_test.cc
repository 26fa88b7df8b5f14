// The robot on its own feet (floating base): it stands under its motors, its links touch what
// stands around it, its kicks keep their balance with the weight shift and topple it without,
// the trials are as deterministic as the fixed base's, and the AIBO's power kick lunges with its
// body.
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/geometry.h"
#include "common/random.h"
#include "models/kick_model.h"
#include "physics/ball_placement.h"
#include "physics/bullet_convert.h"
#include "physics/bullet_world.h"
#include "physics/carpet.h"
#include "physics/kicking_robot.h"
#include "physics/physics_runs.h"
#include "physics/physics_simulator.h"
#include "physics/trial.h"
#include "tests/support/physics_test_scenes.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

std::unique_ptr<testing::PhysicsFixtureData> FloatingNao() {
  auto data = testing::LoadPhysicsFixture("spl", true, "nao");
  data->params.robot.base = RobotBase::kFloating;
  return data;
}

// How far a floating robot held at a kick's stance moves in 2 s on a bare carpet.
struct Standing {
  double drift_m = 0.0;   // horizontal
  double sink_m = 0.0;    // vertical, either way
  double max_tilt_deg = 0.0;
};

Standing StandFor2s(const testing::PhysicsFixtureData& data, const char* kick,
                    const Eigen::Isometry3d& pose_F_start_at_height_0) {
  const Robot& robot = *data.robot;
  const KickMotion& motion = robot.motions[*robot.FindMotion(kick)];
  BulletWorld world(BulletWorld::Kind::kMultiBody, {data.params.steps.solver_iterations,
                                                    data.params.steps.restitution_threshold_mps});
  AddCarpetPlane(world, data.params.materials);
  Eigen::Isometry3d start = pose_F_start_at_height_0;
  start.translation().z() = robot.BaseHeightM(motion);
  KickingRobot kicker(world, robot, start, robot.StandingPositions(motion),
                      KickJoints(robot, motion, RobotBase::kFloating), data.params);
  const Eigen::Vector3d p0 = ToEigen(kicker.body().getBaseWorldTransform()).translation();
  const double dt = data.params.steps.kick_time_step_s;
  Standing standing;
  for (int step = 0; step < 1000; ++step) {  // 2 s
    world.world().stepSimulation(dt, 0, dt);
    standing.max_tilt_deg = std::max(standing.max_tilt_deg, kicker.TiltRad() * kRadToDeg);
  }
  const Eigen::Vector3d p1 = ToEigen(kicker.body().getBaseWorldTransform()).translation();
  standing.drift_m = (p1 - p0).head<2>().norm();
  standing.sink_m = std::abs(p1.z() - p0.z());
  return standing;
}

// Held at a kick's stance by its motors, the robot stands still on its soles: its own contact
// parameters hold it (the ball's striking ones, zero contact ERP and no speculative contacts,
// let it creep 16 mm and tilt 2.8 deg in 2 s).
TEST(FloatingBaseTest, TheRobotStandsStillOnItsSoles) {
  const auto data = FloatingNao();
  for (const char* kick : {"forward", "side_kick_left"}) {
    const Standing standing = StandFor2s(*data, kick, PlanarPose(0.3, -0.2, 0.0, 0.5));
    EXPECT_LT(standing.drift_m, 0.003) << kick;
    EXPECT_LT(standing.sink_m, 0.003) << kick;  // on the carpet, not in it
    EXPECT_LT(standing.max_tilt_deg, 1.0) << kick;
  }
}

// Every link of a floating robot touches the statics (here an obstacle-like box through its
// torso); a fixed base's touch only the ball.
TEST(FloatingBaseTest, ItsLinksTouchTheStaticsAndAFixedBasesDoNot) {
  for (RobotBase base : {RobotBase::kFloating, RobotBase::kFixed}) {
    auto data = testing::LoadPhysicsFixture("spl", true, "nao");
    data->params.robot.base = base;
    const Robot& robot = *data->robot;
    const KickMotion& motion = robot.motions[0];
    BulletWorld world(BulletWorld::Kind::kMultiBody, {10, 0.02});
    AddCarpetPlane(world, data->params.materials);
    auto* box = world.Own(std::make_unique<btBoxShape>(btVector3(0.02, 0.3, 0.02)));
    world.AddStatic(box, btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 0.35)),
                    BodyTag::kObstacle, {0.18, 0.48});
    KickingRobot kicker(world, robot, PlanarPose(0, 0, robot.BaseHeightM(motion), 0),
                        robot.StandingPositions(motion), KickJoints(robot, motion, base),
                        data->params);
    world.world().stepSimulation(0.002, 0, 0.002);
    int robot_contacts = 0;
    btDispatcher& dispatcher = *world.world().getDispatcher();
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      const bool kicker_a = TagOf(*manifold->getBody0()) == BodyTag::kKicker;
      const bool kicker_b = TagOf(*manifold->getBody1()) == BodyTag::kKicker;
      if ((kicker_a || kicker_b) && manifold->getNumContacts() > 0) ++robot_contacts;
    }
    if (base == RobotBase::kFloating) {
      EXPECT_GE(robot_contacts, 2);  // the box and the carpet at least
    } else {
      EXPECT_EQ(robot_contacts, 0);
    }
  }
}

KickTrialsRequest ForwardRequest(const KickModel& kicks, int trials) {
  KickTrialsRequest request;
  const Vec2 ball(-0.3, 0.2);
  request.state = DrawnState{Pose2{ball, 30.0 * kDegToRad}, ball};
  request.kick_index = *kicks.Find("forward");
  request.trials = trials;
  request.seed = 11;
  return request;
}

// With its weight shift the forward kick stands through the kick and launches the ball near the
// issue's 1.0-1.2 m/s.
TEST(FloatingKickTest, TheForwardKickKeepsItsBalanceWithItsWeightShift) {
  const auto data = FloatingNao();
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "nao_calibrated.json");
  const PhysicsSimulator simulator(testing::SceneOf(*data), kicks);
  const std::vector<TrialResult> results = RunKickTrials(simulator, ForwardRequest(kicks, 6));
  const TrialSummary summary = Summarize(results);
  EXPECT_EQ(summary.fell, 0);
  EXPECT_EQ(summary.touched, 6);
  EXPECT_EQ(summary.launched, 6);
  EXPECT_GT(summary.launch_speed_mean_mps, 0.9);
  EXPECT_LT(summary.launch_speed_mean_mps, 1.3);
  EXPECT_LT(summary.max_tilt_rad * kRadToDeg, 20.0);
  for (const TrialResult& r : results) EXPECT_EQ(r.outcome.status, OutcomeStatus::kOk);
}

// Without it the robot lifts its foot with its weight between its soles and topples: the trial
// ends with status fell.
TEST(FloatingKickTest, WithoutItsWeightShiftTheForwardKickFalls) {
  auto data = FloatingNao();
  for (KickMotion& motion : data->robot->motions) motion.balance = KickBalance{};
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "nao_calibrated.json");
  const PhysicsSimulator simulator(testing::SceneOf(*data), kicks);
  const std::vector<TrialResult> results = RunKickTrials(simulator, ForwardRequest(kicks, 3));
  for (const TrialResult& r : results) {
    EXPECT_TRUE(r.fell);
    EXPECT_EQ(r.outcome.status, OutcomeStatus::kFell);
    EXPECT_GT(r.max_tilt_rad, data->params.robot.fall_tilt_rad);
  }
  EXPECT_EQ(CountStatuses(std::vector<Outcome>{results[0].outcome}).fell, 1);
}

TEST(FloatingKickTest, TheSameSeedGivesTheSameTrialsWhateverTheThreads) {
  const auto data = FloatingNao();
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "nao_calibrated.json");
  const PhysicsSimulator simulator(testing::SceneOf(*data), kicks);
  KickTrialsRequest request = ForwardRequest(kicks, 4);
  request.threads = 1;
  const std::vector<TrialResult> one = RunKickTrials(simulator, request);
  request.threads = 2;
  const std::vector<TrialResult> two = RunKickTrials(simulator, request);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].launch_speed_mps, two[i].launch_speed_mps);
    EXPECT_EQ(one[i].launch_direction_rad, two[i].launch_direction_rad);
    EXPECT_EQ(one[i].outcome.p_F_rest, two[i].outcome.p_F_rest);
    EXPECT_EQ(one[i].max_tilt_rad, two[i].max_tilt_rad);
  }
}

// The AIBO on its four paws: held at its stances it stands still (without friction anchors on
// its links' contacts its round paws crept 1.7-2.6 mm/s); its right front paw kicks (`forward`,
// `pass`) stand through the kick with their weight shift and topple without it.
std::unique_ptr<testing::PhysicsFixtureData> FloatingAibo() {
  auto data = testing::LoadPhysicsFixture("four_legged", true, "aibo_ers7");
  data->params.robot.base = RobotBase::kFloating;
  return data;
}

KickTrialsRequest AiboRequest(const KickModel& kicks, const char* kick, int trials) {
  KickTrialsRequest request;
  const Vec2 ball(0.4, -0.3);
  request.state = DrawnState{Pose2{ball, -20.0 * kDegToRad}, ball};
  request.kick_index = *kicks.Find(kick);
  request.trials = trials;
  request.seed = 5;
  return request;
}

TEST(FloatingAiboTest, TheAiboStandsStillOnItsPaws) {
  const auto data = FloatingAibo();
  for (const char* kick : {"forward", "pass", "head_kick_left"}) {
    const Standing standing = StandFor2s(*data, kick, PlanarPose(0.1, 0.2, 0.0, -0.4));
    EXPECT_LT(standing.drift_m, 0.001) << kick;
    EXPECT_LT(standing.sink_m, 0.003) << kick;
    EXPECT_LT(standing.max_tilt_deg, 1.0) << kick;
  }
}

TEST(FloatingAiboTest, ThePawKicksKeepTheirBalanceWithTheirWeightShift) {
  const auto data = FloatingAibo();
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "aibo_ers7.json");
  const PhysicsSimulator simulator(testing::SceneOf(*data), kicks);
  for (const char* kick : {"forward", "pass"}) {
    const TrialSummary summary = Summarize(RunKickTrials(simulator, AiboRequest(kicks, kick, 4)));
    EXPECT_EQ(summary.fell, 0) << kick;
    EXPECT_EQ(summary.launched, 4) << kick;
    EXPECT_GT(summary.launch_speed_mean_mps, 0.6) << kick;
    EXPECT_LT(summary.max_tilt_rad * kRadToDeg, 20.0) << kick;
  }
}

TEST(FloatingAiboTest, WithoutItsWeightShiftTheForwardKickFalls) {
  auto data = FloatingAibo();
  for (KickMotion& motion : data->robot->motions) motion.balance = KickBalance{};
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "aibo_ers7.json");
  const PhysicsSimulator simulator(testing::SceneOf(*data), kicks);
  for (const TrialResult& r : RunKickTrials(simulator, AiboRequest(kicks, "forward", 3))) {
    EXPECT_TRUE(r.fell);
    EXPECT_EQ(r.outcome.status, OutcomeStatus::kFell);
  }
}

// The AIBO's power kick with its body, `power` (models/robots/aibo_ers7/motions/power.json):
// the right front paw strikes while both hind legs lunge the body forward, after UT Austin
// Villa's power kick. On its own paws it stands through the kick, launches the ball faster than
// a floor derived from the published kick, and its ball placement keeps the ball out of the paw
// in nearly every draw of the trial variation.
// The published power kick's launch (models/kicks/aibo_ers7_published.json, `forward`: 50 real
// trials moment-matched to a normal launch, mu 1.077 m/s, s 0.194 m/s). The floor is mu - 2 s, the
// lower edge of the real kick's central 95 %: a body kick whose launches are on average slower
// than most of the real kick's is not a power kick. (The mean itself, which a 1.8 m mean rest
// needs, is out of this body's reach: docs/PHYSICS.md, "The AIBO's power kick with its body".)
double PublishedFloorMps() {
  const KickModel published =
      LoadKickModel(testing::ModelsDir() / "kicks" / "aibo_ers7_published.json");
  const KickSpec& kick = published.kicks[static_cast<std::size_t>(*published.Find("forward"))];
  return kick.speed_mps - 2.0 * kick.sigma_speed_mps;
}

TEST(PowerKickTest, StandsThroughAFixedSeedBatchAndLaunchesAboveThePublishedFloor) {
  const auto data = FloatingAibo();
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "aibo_ers7.json");
  const PhysicsSimulator simulator(testing::SceneOf(*data), kicks);
  const std::vector<TrialResult> results = RunKickTrials(simulator, AiboRequest(kicks, "power", 8));
  const TrialSummary summary = Summarize(results);
  EXPECT_EQ(summary.fell, 0);
  EXPECT_EQ(summary.launched, 8);
  EXPECT_GT(summary.launch_speed_mean_mps, PublishedFloorMps())
      << "largest tilt " << summary.max_tilt_rad * kRadToDeg << " deg";
  for (const TrialResult& r : results) EXPECT_EQ(r.outcome.status, OutcomeStatus::kOk);
}

// The ball lies on the paw's line 30 mm (the placement's 3-sigma clip) ahead of the paw's
// surface, so a placement error reaches into the paw only when the x and the y error are both
// near their clips: at most 1 % of the trial variation's draws are rejected (`forward`'s spot,
// inside the paw, rejects about 70 %), and none of the rest starts inside the body (the placement
// test of every kick, ball_placement_test.cc, checks the trials' own worlds).
TEST(PowerKickTest, PlacementDrawsRarelyReachIntoTheBody) {
  const auto data = FloatingAibo();
  const Robot& robot = *data->robot;
  const KickMotion& motion = robot.motions[static_cast<std::size_t>(*robot.FindMotion("power"))];
  const StanceClearance clearance(robot, motion, data->field.ball.radius_m);
  int inside = 0;
  double nearest_m = 1.0;
  for (std::uint64_t i = 0; i < 1000; ++i) {
    // Unfiltered draws: what a trial would draw without the rejection.
    const TrialDraw draw = DrawTrial(robot.spec.variation, data->params.carpet, StreamKey(21, i));
    const Vec2 p_R_ball = motion.p_R_ball + Vec2(draw.placement_dx_m, draw.placement_dy_m);
    inside += clearance.DepthInsideM(p_R_ball) > 0.0;
    nearest_m = std::min(nearest_m, p_R_ball.x());
  }
  EXPECT_LE(inside, 10) << "of 1000 unfiltered placement draws reach into the body";
  EXPECT_EQ(clearance.DepthInsideM(motion.p_R_ball), 0.0);
  // The test can fail: the ball 3 cm nearer, at the clip, touches the paw.
  EXPECT_GT(clearance.DepthInsideM(motion.p_R_ball - Vec2(0.031, 0.0)), 0.0);
  EXPECT_LT(nearest_m, motion.p_R_ball.x() - 0.02);  // the draws reached towards the body
}

}  // namespace
}  // namespace foresight
