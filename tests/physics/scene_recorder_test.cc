// Scene traces of physics trials (physics/scene_recorder.h): recording changes nothing of the
// trial, the frames keep the rate and end where the ball rests, the link poses agree with the
// ball they strike and the contacts carry the kick's impulse.
#include "physics/scene_recorder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "models/kick_model.h"
#include "physics/physics_simulator.h"
#include "physics/trial.h"
#include "tests/support/physics_test_scenes.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

class SceneRecorderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    data_ = testing::LoadPhysicsFixture("spl", false, "nao").release();
    kicks_ = new KickModel(LoadKickModel(testing::ModelsDir() / "kicks" / "nao.json"));
  }
  static void TearDownTestSuite() {
    delete data_;
    delete kicks_;
  }
  TrialResult Kick(const PhysicsSimulator& simulator, double rate_hz) const {
    const DrawnState state{Pose2{Vec2(-0.3, 0.2), 30.0 * kDegToRad}, Vec2(-0.3, 0.2)};
    ConcreteAction action;
    action.kick_index = *kicks_->Find("forward");
    action.stream = 12345;
    return simulator.Run(state, action, false, rate_hz);
  }
  static testing::PhysicsFixtureData* data_;
  static KickModel* kicks_;
};
testing::PhysicsFixtureData* SceneRecorderTest::data_ = nullptr;
KickModel* SceneRecorderTest::kicks_ = nullptr;

TEST_F(SceneRecorderTest, RecordingChangesNothingOfTheTrial) {
  const PhysicsSimulator simulator(testing::SceneOf(*data_, {}, Vec2(-0.3, 0.2)), *kicks_);
  const TrialResult off = Kick(simulator, 0.0);
  const TrialResult on = Kick(simulator, 100.0);
  EXPECT_FALSE(off.scene.has_value());
  ASSERT_TRUE(on.scene.has_value());
  EXPECT_EQ(off.outcome.p_F_rest.x(), on.outcome.p_F_rest.x());
  EXPECT_EQ(off.outcome.p_F_rest.y(), on.outcome.p_F_rest.y());
  EXPECT_EQ(off.outcome.time_s, on.outcome.time_s);
  EXPECT_EQ(off.launch_speed_mps, on.launch_speed_mps);
}

TEST_F(SceneRecorderTest, FramesKeepTheRateAndEndWhereTheBallRests) {
  const PhysicsSimulator simulator(testing::SceneOf(*data_, {}, Vec2(-0.3, 0.2)), *kicks_);
  const TrialResult r = Kick(simulator, 50.0);
  ASSERT_TRUE(r.scene.has_value());
  const SceneTrace& trace = *r.scene;
  ASSERT_GT(trace.frames.size(), 10u);
  EXPECT_EQ(trace.links.size(), data_->robot->model.links.size());
  for (std::size_t i = 0; i + 1 < trace.frames.size(); ++i) {
    const double gap = trace.frames[i + 1].t_s - trace.frames[i].t_s;
    EXPECT_GT(gap, 0.0) << "frame " << i;
    // Every frame but the last is taken at the first step past a multiple of 20 ms, so two lie
    // at least 20 ms less the longest step apart (one step may overshoot a multiple).
    if (i + 2 < trace.frames.size()) {
      EXPECT_GE(gap, 0.02 - data_->params.steps.free_time_step_s - 1e-9) << "frame " << i;
    }
  }
  // The kick phase's frames hold every link; the roll phase's none (the robot is gone).
  EXPECT_EQ(trace.frames.front().links.size(), trace.links.size());
  EXPECT_TRUE(trace.frames.back().links.empty());
  EXPECT_EQ(trace.phases[trace.frames.back().phase], "roll: ball alone, robot no longer simulated");
  // The last frame is the trial's last step: the ball rests there.
  EXPECT_NEAR(trace.frames.back().ball.p_F.x(), r.outcome.p_F_rest.x(), 1e-12);
  EXPECT_NEAR(trace.frames.back().ball.p_F.y(), r.outcome.p_F_rest.y(), 1e-12);
  EXPECT_NEAR(trace.frames.back().t_s - r.t_first_touch_s, r.outcome.time_s, 1e-9);
}

TEST_F(SceneRecorderTest, TheStrikingFootTouchesTheBallWithTheKicksImpulse) {
  const PhysicsSimulator simulator(testing::SceneOf(*data_, {}, Vec2(-0.3, 0.2)), *kicks_);
  const TrialResult r = Kick(simulator, 1000.0);  // a frame per kick step
  ASSERT_TRUE(r.scene.has_value());
  const SceneTrace& trace = *r.scene;
  double impulse_Ns = 0.0;
  std::string foot;
  for (const SceneContact& c : trace.contacts) {
    EXPECT_EQ(c.a, "ball");  // the carpet's contacts are left out; the robot touches only the ball
    if (c.b == "post" || c.b == "net") continue;
    if (foot.empty()) foot = c.b;
    EXPECT_EQ(c.b, foot);
    impulse_Ns += c.impulse_Ns;
    // The contact lies on the ball's surface, in the frame it was recorded with.
    const auto frame = std::find_if(trace.frames.begin(), trace.frames.end(),
                                    [&](const SceneFrame& f) { return f.t_s == c.t_s; });
    ASSERT_NE(frame, trace.frames.end());
    EXPECT_NEAR((c.p_F - frame->ball.p_F).norm(), data_->field.ball.radius_m, 0.01);
  }
  EXPECT_EQ(foot, "r_foot");
  // The foot's impulse launched the ball. Struck through its centre, a ball slides first and
  // rolls at 1 / (1 + k) of its speed (models/field_spec.h), so the strike's impulse is
  // (1 + k) times its momentum once it rolls (the launch): 1.4 for the solid SPL ball. The foot
  // strikes a little off centre and over several steps, hence the margin.
  const double k = data_->field.ball.inertia_factor;
  const double rolling_momentum_Ns = data_->field.ball.mass_kg * r.launch_speed_mps;
  EXPECT_GT(impulse_Ns, 0.8 * (1.0 + k) * rolling_momentum_Ns);
  EXPECT_LT(impulse_Ns, 1.3 * (1.0 + k) * rolling_momentum_Ns);
}

}  // namespace
}  // namespace foresight
