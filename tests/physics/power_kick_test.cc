// The AIBO's body kick `power` (models/robots/aibo_ers7/motions/power.json), after UT Austin
// Villa's power kick: the robot lunges from its hind legs and both front legs strike the ball
// that lies under its chin. On its own paws (the floating base) it stands through the kick,
// launches the ball faster than a floor derived from the published kick, and its ball placement
// is defined so that no draw of the trial variation can put the ball inside the body.
#include <gtest/gtest.h>

#include <cmath>

#include "common/geometry.h"
#include "common/random.h"
#include "models/kick_model.h"
#include "physics/ball_placement.h"
#include "physics/motion_clearance.h"
#include "physics/physics_runs.h"
#include "physics/physics_simulator.h"
#include "physics/trial.h"
#include "tests/support/physics_test_scenes.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

std::unique_ptr<testing::PhysicsFixtureData> FloatingAibo() {
  auto data = testing::LoadPhysicsFixture("four_legged", true, "aibo_ers7");
  data->params.robot.base = RobotBase::kFloating;
  return data;
}

// A fixed-seed batch from a spot away from the calibration's, the robot turned.
std::vector<TrialResult> PowerTrials(const testing::PhysicsFixtureData& data,
                                     const KickModel& kicks, int trials) {
  const PhysicsSimulator simulator(testing::SceneOf(data), kicks);
  KickTrialsRequest request;
  const Vec2 ball(0.3, 0.4);
  request.state = DrawnState{Pose2{ball, 25.0 * kDegToRad}, ball};
  request.kick_index = *kicks.Find("power");
  request.trials = trials;
  request.seed = 13;
  return RunKickTrials(simulator, request);
}

// The published power kick's launch (models/kicks/aibo_ers7_published.json, `forward`: 50 real
// trials moment-matched to a normal launch, mu 1.077 m/s, s 0.194 m/s). A kick below
// mu - 3 s, the lower edge of the real kick's launches, is not a power kick.
double PublishedFloorMps() {
  const KickModel published =
      LoadKickModel(testing::ModelsDir() / "kicks" / "aibo_ers7_published.json");
  const KickSpec& kick = published.kicks[static_cast<std::size_t>(*published.Find("forward"))];
  return kick.speed_mps - 3.0 * kick.sigma_speed_mps;
}

TEST(PowerKickTest, StandsThroughAFixedSeedBatchAndLaunchesAboveThePublishedFloor) {
  const auto data = FloatingAibo();
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "aibo_ers7.json");
  const std::vector<TrialResult> results = PowerTrials(*data, kicks, 8);
  const TrialSummary summary = Summarize(results);
  EXPECT_EQ(summary.fell, 0);
  EXPECT_EQ(summary.launched, 8);
  EXPECT_LT(summary.max_tilt_rad * kRadToDeg, 35.0);
  EXPECT_GT(summary.launch_speed_mean_mps, PublishedFloorMps());
  for (const TrialResult& r : results) EXPECT_EQ(r.outcome.status, OutcomeStatus::kOk);
}

// The ball lies ahead of the front paws by more than the placement's 3-sigma clip, under the
// raised head, so every draw of the trial variation is clear of the body without rejection (the
// paw kicks' nominal spots lie at or inside the paw, so most of their first draws are rejected).
TEST(PowerKickTest, NoPlacementDrawPutsTheBallInsideTheBody) {
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
  EXPECT_EQ(inside, 0);
  // The test can fail: a ball 10 cm nearer lies in the front paws.
  EXPECT_GT(clearance.DepthInsideM(motion.p_R_ball - Vec2(0.1, 0.0)), 0.005);
  EXPECT_LT(nearest_m, motion.p_R_ball.x() - 0.02);  // the draws reached towards the body
}

// The kick's front legs swing above the carpet; its hind legs lunge by extending against it (by
// the fixed-base forward kinematics of motion_clearance.h they reach below it, which the floating
// base's carpet stops), so only the front legs' clearance is the swing's.
TEST(PowerKickTest, TheFrontLegsSwingAboveTheCarpet) {
  const Robot robot = LoadRobot("aibo_ers7", testing::ModelsDir());
  KickMotion front = robot.motions[static_cast<std::size_t>(*robot.FindMotion("power"))];
  std::vector<std::size_t> keep;
  for (std::size_t j = 0; j < front.joints.size(); ++j) {
    if (front.joints[j].rfind("lf_", 0) == 0 || front.joints[j].rfind("rf_", 0) == 0) keep.push_back(j);
  }
  ASSERT_FALSE(keep.empty());
  std::vector<std::string> joints;
  for (std::size_t j : keep) joints.push_back(front.joints[j]);
  for (KickKeyframe& key : front.keyframes) {
    std::vector<double> q;
    for (std::size_t j : keep) q.push_back(key.positions_rad[j]);
    key.positions_rad = q;
  }
  front.joints = joints;
  EXPECT_GT(FindMotionClearance(robot, front).lowest_m, -0.001);
}

}  // namespace
}  // namespace foresight
