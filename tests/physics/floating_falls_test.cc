// Every shipped NAO kick stands through a fixed-seed batch of trials on the floating base at the
// default trial variation (robot.json's), as the 1000-trial counts of docs/PHYSICS.md do: no trial
// falls, every one launches the ball, and the torso keeps well clear of the fall tilt.
#include <gtest/gtest.h>

#include <string>

#include "common/geometry.h"
#include "models/kick_model.h"
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
}

INSTANTIATE_TEST_SUITE_P(NaoKicks, FloatingFallsTest,
                         ::testing::Values("forward", "forward_long", "side_kick_left",
                                           "side_kick_right"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

}  // namespace
}  // namespace foresight
