// Every shipped NAO kick stands through a fixed-seed batch of trials on the floating base at the
// default trial variation (robot.json's), as the 1000-trial counts of docs/PHYSICS.md do: no trial
// falls, every one launches the ball, the torso keeps well clear of the fall tilt, and the mean
// launch lies in the kick's target band standing (robot.json's launch_min_mps and
// launch_max_mps, with their source; over 1000 trials 1.061, 1.589, 0.737 and 0.740 m/s).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "common/geometry.h"
#include "models/kick_model.h"
#include "models/robot_spec.h"
#include "physics/physics_runs.h"
#include "physics/physics_simulator.h"
#include "tests/support/physics_test_scenes.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

class FloatingFallsTest : public ::testing::TestWithParam<const char*> {};

TEST_P(FloatingFallsTest, ABatchOfTrialsStandsThroughTheKick) {
  auto data = testing::LoadPhysicsFixture("spl", false, "nao");
  data->params.robot.base = RobotBase::kFloating;
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "nao_calibrated.json");
  const PhysicsSimulator simulator(testing::SceneOf(*data), kicks);
  KickTrialsRequest request;
  const Vec2 ball(0.5, -0.4);
  request.state = DrawnState{Pose2{ball, -15.0 * kDegToRad}, ball};
  request.kick_index = *kicks.Find(GetParam());
  request.trials = 12;  // 0 falls in 12 trials: a kick that fell in 1 % of them would pass 89 %
  request.seed = 29;    // of the time, one that falls in a quarter of them 3 %
  request.threads = 2;
  const TrialSummary summary = Summarize(RunKickTrials(simulator, request));
  EXPECT_EQ(summary.fell, 0);
  EXPECT_EQ(summary.launched, request.trials);
  // Half the fall tilt: a kick that sways this far has lost the margin its shift should give.
  EXPECT_LT(summary.max_tilt_rad, 0.5 * data->params.robot.fall_tilt_rad);
  // The mean of 12 launches: its standard error is 0.02-0.04 m/s (sd 0.04-0.13 over 1000).
  const auto& targets = data->robot->spec.launch_targets;
  const auto target = std::find_if(targets.begin(), targets.end(),
                                   [](const auto& t) { return t.first == GetParam(); });
  ASSERT_NE(target, targets.end()) << "robot.json gives " << GetParam() << " no launch target";
  EXPECT_GT(summary.launch_speed_mean_mps, target->second.min_mps);
  if (target->second.max_mps) {
    EXPECT_LT(summary.launch_speed_mean_mps, *target->second.max_mps);
  }
}

INSTANTIATE_TEST_SUITE_P(NaoKicks, FloatingFallsTest,
                         ::testing::Values("forward", "forward_long", "side_kick_left",
                                           "side_kick_right"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

}  // namespace
}  // namespace foresight
