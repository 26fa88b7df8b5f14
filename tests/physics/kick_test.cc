// The robots' kicks in physics: the ball goes where each kick should send it, at a plausible
// speed, and the same seed gives the same trials whatever the thread count.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>

#include "common/geometry.h"
#include "models/kick_model.h"
#include "physics/physics_runs.h"
#include "physics/physics_simulator.h"
#include "physics/trial.h"
#include "tests/support/physics_test_scenes.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

constexpr int kTrials = 12;

struct KickCase {
  const char* robot;
  const char* field;
  const char* kicks;
  const char* kick;
  double direction_deg;  // where the ball must go, in the robot frame
  double tolerance_deg;
  double min_speed_mps;
  double max_speed_mps;
};

void PrintTo(const KickCase& c, std::ostream* os) {
  *os << c.robot << " " << c.kick;
}

class KickTest : public ::testing::TestWithParam<KickCase> {};

TEST_P(KickTest, SendsTheBallTheWayTheKickShould) {
  const KickCase c = GetParam();
  const auto data = testing::LoadPhysicsFixture(c.field, false, c.robot);
  const KickModel kicks =
      LoadKickModel(testing::ModelsDir() / "kicks" / (std::string(c.kicks) + ".json"));
  // The robot at the centre circle, turned 30 degrees, so the kick does not run along an axis.
  const DrawnState state{Pose2{Vec2(-0.3, 0.2), 30.0 * kDegToRad}, Vec2(-0.3, 0.2)};
  const PhysicsSimulator simulator(testing::SceneOf(*data, {}, state.p_F_ball), kicks);
  KickTrialsRequest request;
  request.state = state;
  request.kick_index = *kicks.Find(c.kick);
  request.trials = kTrials;
  request.seed = 11;
  const std::vector<TrialResult> results = RunKickTrials(simulator, request);
  const TrialSummary summary = Summarize(results);
  EXPECT_EQ(summary.touched, kTrials);
  EXPECT_EQ(summary.launched, kTrials);
  EXPECT_EQ(summary.settled, kTrials);
  EXPECT_NEAR(summary.launch_direction_mean_rad * kRadToDeg, c.direction_deg, c.tolerance_deg);
  EXPECT_GT(summary.launch_speed_mean_mps, c.min_speed_mps);
  EXPECT_LT(summary.launch_speed_mean_mps, c.max_speed_mps);
  // The physical causes do make the trials differ.
  EXPECT_GT(summary.launch_speed_sd_mps, 0.0);
  EXPECT_GT(summary.launch_direction_sd_rad, 0.0);
  // The ball rests where its launch direction points, in F.
  const Vec2 travel = summary.rest_mean_F - state.p_F_ball;
  const double travel_deg =
      WrapAngle(std::atan2(travel.y(), travel.x()) - state.robot.theta_rad) * kRadToDeg;
  EXPECT_NEAR(travel_deg, c.direction_deg, c.tolerance_deg + 5.0);
}

INSTANTIATE_TEST_SUITE_P(
    Kicks, KickTest,
    ::testing::Values(
        KickCase{"nao", "spl", "nao", "forward", 0.0, 10.0, 0.5, 3.0},
        // The side kicks sweep the leg out from a straight-legged stance (issue 12, sixth pass):
        // about 0.77 m/s at 92 deg, the paper's model 0.75 m/s at 90.
        KickCase{"nao", "spl", "nao", "side_kick_left", 90.0, 10.0, 0.6, 3.0},
        KickCase{"nao", "spl", "nao", "side_kick_right", -90.0, 10.0, 0.6, 3.0},
        // The strong kick (issue 12: at least 1.5 m/s) is only in the calibrated model; the
        // paper's model keeps the paper's three kicks. It launches about 1.59 m/s from its
        // straight-legged stance, the foot above the carpet (issue 12, sixth pass).
        KickCase{"nao", "spl", "nao_calibrated", "forward_long", 0.0, 10.0, 1.5, 3.0},
        // The standing power kick launches about 0.79 m/s (issue 12, fifth pass); the short
        // strike about 0.24 (its lever, the 65.4 mm lower leg at 4.6 rad/s, moves the paw at
        // about 0.30 m/s; see its motion's notes).
        KickCase{"aibo_ers7", "four_legged", "aibo_ers7", "forward", 0.0, 15.0, 0.7, 3.0},
        KickCase{"aibo_ers7", "four_legged", "aibo_ers7", "forward_short", 0.0, 15.0, 0.15, 3.0},
        // The pass (issue 12, fifth pass) launches about 0.79 m/s, sd 8.6 deg: an accurate kick.
        KickCase{"aibo_ers7", "four_legged", "aibo_ers7", "pass", 0.0, 8.0, 0.65, 3.0},
        KickCase{"aibo_ers7", "four_legged", "aibo_ers7", "head_kick_left", 90.0, 35.0, 0.2, 3.0},
        KickCase{"aibo_ers7", "four_legged", "aibo_ers7", "head_kick_right", -90.0, 35.0, 0.2,
                 3.0}),
    [](const ::testing::TestParamInfo<KickCase>& info) {
      return std::string(info.param.robot) + "_" + info.param.kick;
    });

// A forward strike is a strike, not a push: the ball takes its speed from the foot within a few
// milliseconds of the first touch (it bounces off the foot). Before the contacts realised their
// restitution (issue 12) the foot pushed the ball along for 40-70 ms. (Bullet keeps reporting
// the contact while foot and ball still overlap after the bounce, without any force: the overlap
// is not corrected, see MakeStriking. So the test times the speed, not the contact.) The AIBO's
// `forward` and `pass` push the ball on purpose (their motions' notes: no strike of its paw that
// stays above the carpet gets far), so its pure strike, `forward_short`, is the one timed here:
// until the ball has 95 % of its top speed.
// (With the motors on their torque-speed line the AIBO's paw, still touching, adds the last 1 %
// about 15 ms later; a push would take tens of milliseconds for the first 95 %.)
TEST(KickStrikeTest, ForwardStrikesGiveTheBallItsSpeedWithinAFewMilliseconds) {
  constexpr double kMaxStrikeS = 0.006;
  constexpr double kStruckShare = 0.95;
  constexpr double kMovingShare = 0.05;
  struct Strike {
    const char* robot;
    const char* field;
    const char* kick;
  };
  for (const auto& [robot, field, kick] : {Strike{"nao", "spl", "forward"},
                                           Strike{"nao", "spl", "forward_long"},
                                           Strike{"aibo_ers7", "four_legged", "forward_short"}}) {
    const auto data = testing::LoadPhysicsFixture(field, true, robot);
    const Vec2 ball(-0.3, 0.2);
    KickRequest request;
    request.state = DrawnState{Pose2{ball, 0.0}, ball};
    request.motion_index = *data->robot->FindMotion(kick);
    request.stream = 5;
    request.record_trace = true;
    const TrialResult r = RunKickTrial(testing::SceneOf(*data, {}, ball), request);
    double peak_mps = 0.0;
    for (const TracePoint& p : r.trace) peak_mps = std::max(peak_mps, p.v_F.head<2>().norm());
    // The strike starts where the contact that sets the ball moving (5 % of its top speed)
    // begins; a touch earlier in the motion that leaves the ball at rest (the AIBO's knee
    // brushes it while the leg winds up) is not the strike.
    double touch_start_s = -1.0, strike_start_s = -1.0, struck_s = -1.0;
    bool touching = false;
    for (const TracePoint& p : r.trace) {
      if (p.kicker_contact && !touching) touch_start_s = p.t_s;
      touching = p.kicker_contact;
      const double speed = p.v_F.head<2>().norm();
      if (strike_start_s < 0.0 && speed >= kMovingShare * peak_mps) strike_start_s = touch_start_s;
      if (speed >= kStruckShare * peak_mps) {
        struck_s = p.t_s;
        break;
      }
    }
    ASSERT_GE(strike_start_s, 0.0) << robot << " " << kick;
    EXPECT_LE(struck_s - strike_start_s, kMaxStrikeS) << robot << " " << kick;
    EXPECT_GT(peak_mps, 0.3) << robot << " " << kick;
  }
}

// A touch that leaves the ball (nearly) at rest does not end the kick (issue 12, second pass):
// with the ball 2.2-2.6 cm nearer than the AIBO's `forward_short` wants it (2.7 cm puts it inside
// the leg, which a trial no longer allows: physics/ball_placement.h), the knee brushes the
// ball while the leg winds up (0.02 m/s, far short of the 5 cm roll that counts as a launch); the
// kick phase once took such a graze for a launch and never played the strike (then 6 % of the
// old crouched `forward`'s trials). The motion goes on and the strike launches the ball, more
// than 0.1 s after that first touch.
TEST(KickPhaseTest, AGrazeThatLeavesTheBallAtRestDoesNotEndTheKick) {
  const auto data = testing::LoadPhysicsFixture("four_legged", true, "aibo_ers7");
  data->robot->spec.variation = TrialVariation{};  // exactly the placement below
  const int kick = *data->robot->FindMotion("forward_short");
  const Vec2 nominal = data->robot->motions[kick].p_R_ball;
  for (const double nearer_m : {0.022, 0.026}) {
    data->robot->motions[kick].p_R_ball = nominal - Vec2(nearer_m, 0.0);
    const Vec2 ball(-0.88, 0.0);
    KickRequest request;
    request.state = DrawnState{Pose2{Vec2(-1.0, 0.0), 0.0}, ball};
    request.motion_index = kick;
    request.stream = 1;
    const TrialResult r = RunKickTrial(testing::SceneOf(*data, {}, ball), request);
    EXPECT_TRUE(r.touched) << nearer_m;
    EXPECT_TRUE(r.launched) << nearer_m;
    EXPECT_GT(r.t_launch_s, 0.1) << nearer_m;  // the graze came first
    EXPECT_GT(r.launch_speed_mps, 0.2) << nearer_m;
    EXPECT_GT((r.outcome.p_F_rest - ball).norm(), 0.08) << nearer_m;
  }
}

// The strike is when the robot's touch gives the ball a launch's speed, by the rule the kick phase
// tells a graze from a launch with: after the graze above (the knee brushing the ball, which it
// leaves nearly at rest) the strike comes later, with the contact that carries the kick's impulse
// (the largest in the recorded scene). The viewer shows both times.
TEST(KickPhaseTest, TheStrikeIsTheLaunchingTouchNotAnEarlierGraze) {
  const auto data = testing::LoadPhysicsFixture("four_legged", true, "aibo_ers7");
  data->robot->spec.variation = TrialVariation{};
  const int kick = *data->robot->FindMotion("forward_short");
  data->robot->motions[kick].p_R_ball -= Vec2(0.022, 0.0);
  const Vec2 ball(-0.88, 0.0);
  KickRequest request;
  request.state = DrawnState{Pose2{Vec2(-1.0, 0.0), 0.0}, ball};
  request.motion_index = kick;
  request.stream = 1;
  request.scene_rate_hz = 100.0;
  const TrialResult r = RunKickTrial(testing::SceneOf(*data, {}, ball), request);
  ASSERT_TRUE(r.launched);
  EXPECT_GT(r.t_strike_s, r.t_first_touch_s + 0.05);  // the graze came first
  ASSERT_TRUE(r.scene.has_value());
  double largest = 0.0, t_largest = -1.0;
  for (const SceneContact& c : r.scene->contacts) {
    const std::string& other = c.a == "ball" ? c.b : c.a;
    const bool link = other != "ball" && other != "carpet" && other != "post" && other != "net" &&
                      other != "obstacle";
    if ((c.a == "ball" || c.b == "ball") && link && c.impulse_Ns > largest) {
      largest = c.impulse_Ns;
      t_largest = c.t_s;
    }
  }
  // Contacts are summed over a frame's 10 ms; a strike lasts a few milliseconds.
  EXPECT_GE(t_largest, r.t_strike_s - 0.01);
  EXPECT_LE(t_largest, r.t_strike_s + 0.02);
  // A kick without a graze: the strike comes within the few milliseconds a strike takes
  // (KickStrikeTest) of the first touch.
  data->robot->motions[kick].p_R_ball += Vec2(0.022, 0.0);
  const TrialResult clean = RunKickTrial(testing::SceneOf(*data, {}, ball), request);
  ASSERT_TRUE(clean.launched);
  EXPECT_GE(clean.t_strike_s, clean.t_first_touch_s);
  EXPECT_LE(clean.t_strike_s, clean.t_first_touch_s + 0.006);
}

// The seam says when the robot missed (issue 11): with the ball moved half a metre to the side of
// where the motion expects it, the foot swings through air, the ball stays, and the outcome says
// so; the same kick at the right place says ok.
TEST(KickStatusTest, AMissedBallIsReportedAsMissed) {
  const auto data = testing::LoadPhysicsFixture("spl", true, "nao");
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "nao.json");
  const DrawnState state{Pose2{Vec2(-0.3, 0.2), 0.0}, Vec2(-0.3, 0.2)};
  const ConcreteAction forward{*kicks.Find("forward"), 0.0, 0.0, 0.0, 5};
  const PhysicsSimulator hits(testing::SceneOf(*data, {}, state.p_F_ball), kicks);
  const Outcome hit = hits.Simulate(state, forward);
  EXPECT_EQ(hit.status, OutcomeStatus::kOk);
  EXPECT_GT((hit.p_F_rest - state.p_F_ball).norm(), 0.2);

  for (KickMotion& motion : data->robot->motions) motion.p_R_ball.y() += 0.5;
  const PhysicsSimulator misses(testing::SceneOf(*data, {}, state.p_F_ball), kicks);
  const TrialResult miss = misses.Run(state, forward, false);
  EXPECT_FALSE(miss.touched);
  EXPECT_EQ(miss.outcome.status, OutcomeStatus::kMissed);
  EXPECT_LT((miss.outcome.p_F_rest - state.p_F_ball).norm(), 1e-3);
  EXPECT_EQ(CountStatuses({&miss.outcome, 1}).missed, 1);
}

TEST(KickDeterminismTest, SameSeedSameTrialsWithOneThreadOrSeveral) {
  const auto data = testing::LoadPhysicsFixture("spl", false, "nao");
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "nao.json");
  const DrawnState state{Pose2{Vec2(3.2, 0.5), 10.0 * kDegToRad}, Vec2(3.35, 0.5)};
  const PhysicsSimulator simulator(testing::SceneOf(*data, {}, state.p_F_ball), kicks);
  KickTrialsRequest request;
  request.state = state;
  request.kick_index = 0;
  request.trials = 6;
  request.seed = 99;
  request.threads = 1;
  const std::vector<TrialResult> one = RunKickTrials(simulator, request);
  request.threads = 3;
  const std::vector<TrialResult> several = RunKickTrials(simulator, request);
  ASSERT_EQ(one.size(), several.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    // Bit-identical, not merely close.
    EXPECT_EQ(one[i].outcome.p_F_rest.x(), several[i].outcome.p_F_rest.x()) << i;
    EXPECT_EQ(one[i].outcome.p_F_rest.y(), several[i].outcome.p_F_rest.y()) << i;
    EXPECT_EQ(one[i].outcome.time_s, several[i].outcome.time_s) << i;
    EXPECT_EQ(one[i].launch_speed_mps, several[i].launch_speed_mps) << i;
    EXPECT_EQ(one[i].outcome.category, several[i].outcome.category) << i;
  }
  // And different trials really differ.
  EXPECT_NE(one[0].outcome.p_F_rest.x(), one[1].outcome.p_F_rest.x());
}

TEST(KickNoiseTest, PhysicsNeverSamplesTheKickModelsSigmas) {
  // Calibration measures sigma_v and sigma_alpha from physics, so physics must not use them:
  // trials with the sigmas multiplied by ten are bit-identical.
  const auto data = testing::LoadPhysicsFixture("spl", false, "nao");
  const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "nao.json");
  KickModel noisy = kicks;
  for (KickSpec& k : noisy.kicks) {
    k.sigma_speed_mps *= 10.0;
    k.sigma_direction_rad *= 10.0;
  }
  const DrawnState state{Pose2{Vec2(0.0, 0.0), 0.0}, Vec2(0.18, -0.05)};
  const PhysicsSimulator plain(testing::SceneOf(*data, {}, state.p_F_ball), kicks);
  const PhysicsSimulator wide(testing::SceneOf(*data, {}, state.p_F_ball), noisy);
  KickTrialsRequest request;
  request.state = state;
  request.trials = 3;
  request.seed = 5;
  const std::vector<TrialResult> a = RunKickTrials(plain, request);
  const std::vector<TrialResult> b = RunKickTrials(wide, request);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].launch_speed_mps, b[i].launch_speed_mps) << i;
    EXPECT_EQ(a[i].outcome.p_F_rest.x(), b[i].outcome.p_F_rest.x()) << i;
  }
}

}  // namespace
}  // namespace foresight
