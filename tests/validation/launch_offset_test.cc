// The launch offset (issue 12): where free rolling starts, fitted by calibration so that the
// calibrated coarse model rests where physics does. A synthetic fit with a known answer, and the
// NAO's forward kick in physics against the coarse roll of its calibrated model.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/random.h"
#include "models/situation.h"
#include "planner/coarse_planner.h"
#include "tests/support/temp_files.h"
#include "validation/calibration.h"
#include "validation/physics_calibration.h"

namespace foresight {
namespace {

// Kicks whose balls roll freely from `offset_m` ahead of where they lay, at speeds around 1.1 m/s
// with 2 cm of noise on the roll and 5 mm on the launch point, on a carpet of a = 0.27 m/s^2.
std::vector<KickObservation> SyntheticKicks(double offset_m, int n, std::uint64_t seed) {
  constexpr double kA = 0.27;
  RandomStream rng(StreamKey(seed, 0));
  std::vector<KickObservation> kicks;
  for (int i = 0; i < n; ++i) {
    KickObservation k;
    k.launch_speed_mps = 1.1 + 0.05 * rng.NextNormal();
    const double launch_point_m = offset_m + 0.005 * rng.NextNormal();
    k.launch_offset_m = launch_point_m;
    k.has_launch_offset = true;
    k.roll_distance_m = k.launch_speed_mps * k.launch_speed_mps / (2.0 * kA) +
                        (offset_m - launch_point_m) + 0.02 * rng.NextNormal();
    k.has_roll_distance = true;
    kicks.push_back(k);
  }
  return kicks;
}

TEST(LaunchOffsetTest, TheFitRecoversAKnownOffset) {
  for (double offset : {0.0, 0.05, 0.12}) {
    const std::optional<LaunchOffsetFit> fit =
        FitLaunchOffset(SyntheticKicks(offset, 400, 7), 0.27);
    ASSERT_TRUE(fit.has_value());
    EXPECT_EQ(fit->kicks, 400);
    // The standard error is 2 cm / sqrt(400) = 1 mm: within 3 of them.
    EXPECT_NEAR(fit->standard_error_m, 0.001, 0.0002) << offset;
    EXPECT_NEAR(fit->unclamped_offset_m, offset, 0.003) << offset;
    EXPECT_NEAR(fit->launch_point_m, offset, 0.001) << offset;
    EXPECT_GE(fit->offset_m, 0.0);
  }
}

TEST(LaunchOffsetTest, BallsRestingShortOfTheirSpeedAreClampedAtZero) {
  // A carpet that is really 0.29 m/s^2 read as 0.27: the balls rest 16 cm short.
  std::vector<KickObservation> kicks = SyntheticKicks(0.0, 200, 3);
  for (KickObservation& k : kicks) {
    k.roll_distance_m = k.launch_speed_mps * k.launch_speed_mps / (2.0 * 0.29);
  }
  const std::optional<LaunchOffsetFit> fit = FitLaunchOffset(kicks, 0.27);
  ASSERT_TRUE(fit.has_value());
  EXPECT_LT(fit->unclamped_offset_m, -0.1);
  EXPECT_EQ(fit->offset_m, 0.0);
}

TEST(LaunchOffsetTest, KicksWithoutLaunchPointsGiveNoFit) {
  std::vector<KickObservation> log = SyntheticKicks(0.05, 50, 1);
  for (KickObservation& k : log) k.has_launch_offset = false;  // a real robot's log
  EXPECT_FALSE(FitLaunchOffset(log, 0.27).has_value());
  EXPECT_FALSE(FitLaunchOffset(SyntheticKicks(0.05, 1, 1), 0.27).has_value());
}

// The distance from where the ball lay to where it rests over a run's physics trials: its mean
// and the standard error of that mean.
struct RestDistance {
  double mean_m = 0.0;
  double standard_error_m = 0.0;
};
RestDistance PhysicsRestDistance(const PhysicsCalibration& run) {
  std::vector<double> d;
  for (const KickObservation& k : run.kicks[0].observations) {
    if (k.has_launch_offset) d.push_back(k.launch_offset_m + k.roll_distance_m);
  }
  EXPECT_GT(d.size(), 250u);
  const double n = static_cast<double>(d.size());
  double sum = 0.0, sum_sq = 0.0;
  for (double x : d) sum += x;
  const double mean = sum / n;
  for (double x : d) sum_sq += (x - mean) * (x - mean);
  return {mean, std::sqrt(sum_sq / (n - 1.0) / n)};
}

// The same for the coarse model: the calibration situation's ball rolled by `model`'s forward
// kick, 20,000 samples through the planner's evaluator.
double CoarseMeanRestDistance(const KickModel& model) {
  Situation s =
      LoadSituation(testing::ModelsDir() / "calibration" / "nao.json", testing::ModelsDir());
  s.kicks = model;
  const CoarsePlanner planner(s);
  const CoarseActionEvaluator evaluator = planner.MakeEvaluator(20000, 5);
  const Vec2 ball = s.state.MeanBallInField();
  double sum = 0.0;
  const std::vector<Outcome> outcomes = evaluator.Outcomes(0, 0.0);
  for (const Outcome& o : outcomes) sum += (o.p_F_rest - ball).norm();
  return sum / static_cast<double>(outcomes.size());
}

// Fitted on one seed's trials, judged on another's: the calibrated coarse model's mean rest
// agrees with physics within three standard errors of the two runs' means (the fit inherits the
// fitting run's sampling error; about 3 cm at 300 trials), and is short by about the offset
// without it.
TEST(LaunchOffsetTest, CalibratedCoarseRestsMatchPhysicsForTheNaoForwardKick) {
  PhysicsCalibrationSettings settings;
  settings.robot = "nao";
  settings.kick = "forward";
  settings.trials = 300;
  settings.threads = 2;
  settings.seed = 1;
  // The fixed base, the cheap approximation (a tenth of a floating trial's cost): the fit and
  // the judging runs are both its own, so the test holds the launch offset's fit on either base.
  settings.base = RobotBase::kFixed;
  const PhysicsCalibration fit_run = RunPhysicsCalibration(settings, testing::ModelsDir());
  settings.seed = 2;
  const PhysicsCalibration judge_run = RunPhysicsCalibration(settings, testing::ModelsDir());

  CalibrationSettings fit_settings;
  fit_settings.resamples = 100;
  const std::vector<KickObservation>& observed = fit_run.kicks[0].observations;
  KickCalibration kick = CalibrateKick("forward", observed, fit_settings);
  const std::optional<DecelerationFit> a = FitPooledDeceleration(observed, fit_settings);
  ASSERT_TRUE(a.has_value());
  kick.launch_offset = FitLaunchOffset(observed, a->deceleration_mps2);
  ASSERT_TRUE(kick.launch_offset.has_value());
  const KickModel with_offset = ApplyCalibration(fit_run.model, {&kick, 1}, a);
  KickModel without = with_offset;
  without.kicks[0].launch_offset_m = 0.0;

  const RestDistance fitted = PhysicsRestDistance(fit_run);
  const RestDistance physics = PhysicsRestDistance(judge_run);
  const double tolerance_m = 3.0 * std::hypot(fitted.standard_error_m, physics.standard_error_m);
  const double offset_m = with_offset.kicks[0].launch_offset_m;
  EXPECT_GT(offset_m, 0.02);               // the ball does slide first
  ASSERT_LT(tolerance_m, 0.5 * offset_m);  // else the test could not tell the offset's effect
  EXPECT_NEAR(CoarseMeanRestDistance(with_offset), physics.mean_m, tolerance_m);
  EXPECT_LT(CoarseMeanRestDistance(without), physics.mean_m - tolerance_m);
}

}  // namespace
}  // namespace foresight
