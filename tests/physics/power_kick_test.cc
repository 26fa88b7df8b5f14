// The AIBO's power kick with its body, `power` (models/robots/aibo_ers7/motions/power.json):
// the right front paw strikes while both hind legs lunge the body forward, after UT Austin
// Villa's power kick. On its own paws (the floating base) it stands through the kick, launches
// the ball faster than a floor derived from the published kick, and its ball placement keeps
// the ball out of the paw in nearly every draw of the trial variation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/geometry.h"
#include "common/random.h"
#include "models/kick_model.h"
#include "physics/ball_placement.h"
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
  std::printf("power: launch %.3f m/s mean over %d trials, largest tilt %.1f deg\n",
              summary.launch_speed_mean_mps, summary.launched, summary.max_tilt_rad * kRadToDeg);
  EXPECT_GT(summary.launch_speed_mean_mps, PublishedFloorMps());
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
  std::printf("power: %d of 1000 unfiltered placement draws reach into the body\n", inside);
  EXPECT_LE(inside, 10);
  EXPECT_EQ(clearance.DepthInsideM(motion.p_R_ball), 0.0);
  // The test can fail: the ball 3 cm nearer, at the clip, touches the paw.
  EXPECT_GT(clearance.DepthInsideM(motion.p_R_ball - Vec2(0.031, 0.0)), 0.0);
  EXPECT_LT(nearest_m, motion.p_R_ball.x() - 0.02);  // the draws reached towards the body
}

}  // namespace
}  // namespace foresight
