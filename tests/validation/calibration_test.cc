// Calibrating a kick from observations: the self-check (a sample drawn from a known
// model gives that model back), the normality test, the pooled deceleration, what a physics
// trial shows of its kick, and writing the fit into a kick model.
#include "validation/calibration.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/geometry.h"
#include "common/random.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

constexpr double kSpeed = 0.8;
constexpr double kSigmaSpeed = 0.06;
constexpr double kDirection = 90.0 * kDegToRad;
constexpr double kSigmaDirection = 2.0 * kDegToRad;  // variance 4 deg^2

// n kicks from the known model: v0 ~ N(0.8, 0.06^2), alpha ~ N(90 deg, (2 deg)^2).
std::vector<KickObservation> DrawKicks(int n, std::uint64_t seed) {
  RandomStream stream(StreamKey(seed, 0));
  std::vector<KickObservation> kicks(static_cast<std::size_t>(n));
  for (KickObservation& k : kicks) {
    k.launch_speed_mps = kSpeed + kSigmaSpeed * stream.NextNormal();
    k.launch_direction_rad = kDirection + kSigmaDirection * stream.NextNormal();
  }
  return kicks;
}

CalibrationSettings Settings(int resamples = 1000) {
  CalibrationSettings s;
  s.resamples = resamples;
  s.seed = 5;
  return s;
}

// Issue 16: identical rows (or all directions recorded as one number) are ordinary data, not an
// internal error: the spread is 0 and the normality test says it could not be computed.
TEST(CalibrationTest, IdenticalKicksFitWithZeroSpread) {
  KickObservation k;
  k.launch_speed_mps = 0.7;
  k.launch_direction_rad = 0.1;
  const std::vector<KickObservation> kicks(20, k);
  const KickCalibration c = CalibrateKick("forward", kicks, Settings(200));
  EXPECT_NEAR(c.speed.mean, 0.7, 1e-12);
  EXPECT_NEAR(c.speed.sd, 0.0, 1e-12);
  EXPECT_NEAR(c.direction.mean_rad, 0.1, 1e-12);
  EXPECT_NEAR(c.direction.sd_rad, 0.0, 1e-6);
  EXPECT_TRUE(c.speed_normality.all_equal);
  EXPECT_TRUE(c.direction_normality.all_equal);
  EXPECT_FALSE(c.speed_normality.Rejected(0.05));
}

TEST(CalibrationTest, SelfCheckRecoversTheModelThatDrewTheKicks) {
  const std::vector<KickObservation> kicks = DrawKicks(1000, 1);
  const KickCalibration c = CalibrateKick("side_kick_left", kicks, Settings());
  EXPECT_EQ(c.kick, "side_kick_left");
  EXPECT_EQ(c.observations, 1000);
  EXPECT_EQ(c.speed.n, 1000);
  EXPECT_NEAR(c.speed.mean, kSpeed, 0.05 * kSpeed);
  EXPECT_NEAR(c.speed.sd, kSigmaSpeed, 0.05 * kSigmaSpeed);
  EXPECT_NEAR(c.direction.mean_rad, kDirection, 0.5 * kDegToRad);
  EXPECT_NEAR(c.direction.sd_rad, kSigmaDirection, 0.05 * kSigmaDirection);
  EXPECT_TRUE(c.speed.mean_ci.Contains(kSpeed))
      << c.speed.mean_ci.low << " " << c.speed.mean_ci.high;
  EXPECT_TRUE(c.speed.sd_ci.Contains(kSigmaSpeed))
      << c.speed.sd_ci.low << " " << c.speed.sd_ci.high;
  EXPECT_TRUE(c.direction.mean_ci_rad.Contains(kDirection))
      << c.direction.mean_ci_rad.low << " " << c.direction.mean_ci_rad.high;
  EXPECT_TRUE(c.direction.sd_ci_rad.Contains(kSigmaDirection))
      << c.direction.sd_ci_rad.low << " " << c.direction.sd_ci_rad.high;
  // The intervals are real intervals around the estimates, not points.
  EXPECT_LT(c.speed.mean_ci.low, c.speed.mean);
  EXPECT_GT(c.direction.sd_ci_rad.high, c.direction.sd_rad);
  EXPECT_FALSE(c.speed_normality.Rejected(0.05)) << c.speed_normality.anderson_darling_p;
  EXPECT_FALSE(c.direction_normality.Rejected(0.05)) << c.direction_normality.anderson_darling_p;
  EXPECT_EQ(c.speed_qq.size(), 1000u);
  EXPECT_EQ(c.direction_unwrapped_rad.size(), 1000u);
  EXPECT_FALSE(c.deceleration.has_value());  // no rolling samples, no roll distances

  // ... and written into a kick model, the numbers a planner would use.
  const KickModel model =
      ApplyCalibration(LoadKickModel(testing::ModelsDir() / "kicks" / "nao.json"),
                       std::vector<KickCalibration>{c}, std::nullopt);
  const KickSpec& spec = model.kicks[*model.Find("side_kick_left")];
  EXPECT_NEAR(spec.speed_mps, kSpeed, 0.05 * kSpeed);
  EXPECT_NEAR(spec.direction_rad, kDirection, 0.5 * kDegToRad);
}

TEST(CalibrationTest, DirectionsAcrossTheBackAreFittedOnTheCircle) {
  // Kicks straight back: the directions straddle +-pi, a plain mean would say about 0.
  std::vector<KickObservation> kicks = DrawKicks(200, 8);
  for (KickObservation& k : kicks)
    k.launch_direction_rad = WrapAngle(k.launch_direction_rad + kDirection);
  const KickCalibration c = CalibrateKick("back", kicks, Settings(300));
  EXPECT_NEAR(std::abs(c.direction.mean_rad), std::numbers::pi, 1.0 * kDegToRad);
  EXPECT_NEAR(c.direction.sd_rad, kSigmaDirection, 0.15 * kSigmaDirection);
}

TEST(CalibrationTest, NormalityTestFlagsSkewedSpeedsOnly) {
  RandomStream stream(StreamKey(11, 3));
  std::vector<KickObservation> skewed = DrawKicks(200, 12);
  for (KickObservation& k : skewed) {
    k.launch_speed_mps = 0.5 - 0.1 * std::log(1.0 - stream.NextUniform());  // exponential tail
  }
  const KickCalibration bad = CalibrateKick("forward", skewed, Settings(200));
  EXPECT_TRUE(bad.speed_normality.Rejected(0.05)) << bad.speed_normality.anderson_darling_p;
  EXPECT_LT(bad.speed_normality.anderson_darling_p, 0.001);
  EXPECT_GT(bad.speed.skewness, 1.0);

  const KickCalibration good = CalibrateKick("forward", DrawKicks(200, 1), Settings(200));
  EXPECT_FALSE(good.speed_normality.Rejected(0.05)) << good.speed_normality.anderson_darling_p;
  EXPECT_LT(std::abs(good.speed.skewness), 0.5);
}

TEST(CalibrationTest, FewerThanEightKicksIsAnInputErrorNamingTheKick) {
  const std::vector<KickObservation> seven = DrawKicks(7, 1);
  try {
    CalibrateKick("side_kick_right", seven, Settings(100));
    FAIL() << "7 kicks were accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("side_kick_right"));
    EXPECT_THAT(e.what(), HasSubstr("7"));
  }
  EXPECT_THROW(CalibrateKick("forward", std::vector<KickObservation>{}, Settings(100)), InputError);
  const KickCalibration eight = CalibrateKick("forward", DrawKicks(8, 1), Settings(100));
  EXPECT_EQ(eight.observations, 8);
}

// Kick i rolls from its own launch speed and time; every 0.05 s, `noise_sd` speed noise.
KickObservation Rolling(int i, double deceleration, double noise_sd) {
  RandomStream stream(StreamKey(99, static_cast<std::uint64_t>(i)));
  KickObservation k;
  k.launch_speed_mps = 0.6 + 0.1 * i;
  const double t0 = 0.3 + 0.07 * i;
  for (int j = 0; j < 30; ++j) {
    const double t = t0 + 0.05 * j;
    k.rolling.push_back(
        {t, k.launch_speed_mps - deceleration * (t - t0) + noise_sd * stream.NextNormal()});
  }
  return k;
}

TEST(CalibrationTest, PooledDecelerationFromRollingSamples) {
  std::vector<KickObservation> kicks;
  for (int i = 0; i < 10; ++i) kicks.push_back(Rolling(i, 0.27, 0.003));
  const std::optional<DecelerationFit> fit = FitPooledDeceleration(kicks, Settings(500));
  ASSERT_TRUE(fit.has_value());
  EXPECT_NEAR(fit->deceleration_mps2, 0.27, 0.01 * 0.27);
  EXPECT_EQ(fit->trials, 10);
  EXPECT_EQ(fit->samples, 300);
  EXPECT_TRUE(fit->ci_mps2.Contains(0.27)) << fit->ci_mps2.low << " " << fit->ci_mps2.high;
}

TEST(CalibrationTest, PooledDecelerationFromRollDistancesIsExactForExactData) {
  constexpr double kA = 0.27;
  std::vector<KickObservation> kicks = DrawKicks(12, 4);
  for (KickObservation& k : kicks) {
    k.roll_distance_m = k.launch_speed_mps * k.launch_speed_mps / (2.0 * kA);
    k.has_roll_distance = true;
  }
  const std::optional<DecelerationFit> fit = FitPooledDeceleration(kicks, Settings(300));
  ASSERT_TRUE(fit.has_value());
  EXPECT_NEAR(fit->deceleration_mps2, kA, 1e-9 * kA);
  EXPECT_EQ(fit->trials, 12);
  EXPECT_NEAR(fit->ci_mps2.low, kA, 1e-9 * kA);
  EXPECT_NEAR(fit->ci_mps2.high, kA, 1e-9 * kA);
  EXPECT_NEAR(fit->residual_sd_mps, 0.0, 1e-9);
}

TEST(CalibrationTest, RollingSamplesWinOverRollDistancesAndNeitherGivesNothing) {
  std::vector<KickObservation> kicks;
  for (int i = 0; i < 4; ++i) {
    KickObservation k = Rolling(i, 0.27, 0.0);
    k.roll_distance_m = k.launch_speed_mps * k.launch_speed_mps / (2.0 * 0.5);  // says a = 0.5
    k.has_roll_distance = true;
    kicks.push_back(k);
  }
  const std::optional<DecelerationFit> fit = FitPooledDeceleration(kicks, Settings(200));
  ASSERT_TRUE(fit.has_value());
  EXPECT_NEAR(fit->deceleration_mps2, 0.27, 1e-9);

  EXPECT_FALSE(FitPooledDeceleration(DrawKicks(20, 2), Settings(200)).has_value());
  EXPECT_FALSE(FitPooledDeceleration(std::vector<KickObservation>{}, Settings(200)).has_value());
  // A single kick with either is not enough to fit.
  std::vector<KickObservation> lone = DrawKicks(20, 2);
  lone[3] = Rolling(3, 0.27, 0.0);
  lone[5].roll_distance_m = 1.0;
  lone[5].has_roll_distance = true;
  EXPECT_FALSE(FitPooledDeceleration(lone, Settings(200)).has_value());
}

constexpr double kRadius = 0.05;

TracePoint Point(double t, double z, double vx, double vy) {
  TracePoint p;
  p.t_s = t;
  p.p_F = Eigen::Vector3d(t, 0.0, z);
  p.v_F = Eigen::Vector3d(vx, vy, 0.0);
  return p;
}

// A kick touched at t = 0.4 s of the motion, rolling freely from 0.25 s later (t = 0.65 s).
TrialResult HandMadeTrial() {
  TrialResult trial;
  trial.touched = trial.launched = trial.settled = true;
  trial.launch_speed_mps = 1.1;
  trial.launch_direction_rad = 0.3;
  trial.p_F_launch = Vec2(1.0, 2.0);
  trial.outcome.p_F_rest = Vec2(4.0, 6.0);  // 5 m away
  trial.t_first_touch_s = 0.4;
  trial.t_launch_s = 0.25;
  for (int j = 0; j < 6; ++j)
    trial.trace.push_back(Point(0.4 + 0.04 * j, kRadius, 2.0, 0.0));  // sliding
  return trial;
}

TEST(CalibrationTest, ObservationOfKeepsOnlyTheFreeRoll) {
  TrialResult trial = HandMadeTrial();
  std::vector<SpeedSample> rolling;
  for (int j = 0; j < 5; ++j) {
    const double t = 0.65 + 0.1 * j;
    const double speed = 1.0 - 0.27 * (t - 0.65);
    trial.trace.push_back(Point(t, kRadius + 2e-4, 0.6 * speed, 0.8 * speed));
    rolling.push_back({t, speed});
  }
  trial.trace.push_back(Point(1.15, kRadius + 0.01, 0.7, 0.0));  // a bounce
  trial.trace.push_back(Point(1.25, kRadius, 0.7, 0.0));         // rolls again: not free any more
  const KickObservation k = ObservationOf(trial, kRadius);
  EXPECT_DOUBLE_EQ(k.launch_speed_mps, 1.1);
  EXPECT_DOUBLE_EQ(k.launch_direction_rad, 0.3);
  EXPECT_TRUE(k.has_roll_distance);
  EXPECT_NEAR(k.roll_distance_m, 5.0, 1e-12);
  ASSERT_EQ(k.rolling.size(), rolling.size());
  for (std::size_t i = 0; i < rolling.size(); ++i) {
    EXPECT_DOUBLE_EQ(k.rolling[i].t_s, rolling[i].t_s);
    EXPECT_NEAR(k.rolling[i].speed_mps, rolling[i].speed_mps, 1e-12);
  }
}

TEST(CalibrationTest, ObservationOfStopsBelowTheMinimumSpeed) {
  TrialResult trial = HandMadeTrial();
  trial.settled = false;
  const double speeds[] = {0.5, 0.35, 0.21, 0.19, 0.25, 0.1};
  for (int j = 0; j < 6; ++j)
    trial.trace.push_back(Point(0.65 + 0.1 * j, kRadius, 0.0, -speeds[j]));
  const KickObservation k = ObservationOf(trial, kRadius);
  EXPECT_FALSE(k.has_roll_distance);  // it did not come to rest
  ASSERT_EQ(k.rolling.size(), 3u);
  EXPECT_NEAR(k.rolling.back().speed_mps, 0.21, 1e-12);
  // A lower threshold keeps more.
  EXPECT_EQ(ObservationOf(trial, kRadius, 0.15).rolling.size(), 5u);
}

TEST(CalibrationTest, ObservationOfABallThatHitAPostHasNoRoll) {
  TrialResult trial = HandMadeTrial();
  for (int j = 0; j < 5; ++j) trial.trace.push_back(Point(0.65 + 0.1 * j, kRadius, 1.0, 0.0));
  ASSERT_EQ(ObservationOf(trial, kRadius).rolling.size(), 5u);
  trial.outcome.first_contact = Contact::kPost;
  const KickObservation k = ObservationOf(trial, kRadius);
  EXPECT_TRUE(k.rolling.empty());
  EXPECT_FALSE(k.has_roll_distance);
  EXPECT_DOUBLE_EQ(k.launch_speed_mps, 1.1);  // the launch is still seen
}

KickCalibration Fitted(const std::string& kick, double speed, double sigma_speed,
                       double direction_rad, double sigma_direction_rad) {
  KickCalibration c;
  c.kick = kick;
  c.speed.mean = speed;
  c.speed.sd = sigma_speed;
  c.direction.mean_rad = direction_rad;
  c.direction.sd_rad = sigma_direction_rad;
  return c;
}

TEST(CalibrationTest, ApplyCalibrationReplacesOnlyTheCalibratedKicks) {
  const KickModel base = LoadKickModel(testing::ModelsDir() / "kicks" / "nao.json");
  const std::vector<KickCalibration> fits = {Fitted("side_kick_left", 0.51, 0.03, 1.58, 0.04)};
  DecelerationFit deceleration;
  deceleration.deceleration_mps2 = 0.31;
  const KickModel model = ApplyCalibration(base, fits, deceleration);
  EXPECT_EQ(model.robot, base.robot);
  EXPECT_DOUBLE_EQ(model.rolling_deceleration_mps2, 0.31);
  ASSERT_EQ(model.kicks.size(), base.kicks.size());
  for (std::size_t i = 0; i < base.kicks.size(); ++i) {
    const KickSpec& got = model.kicks[i];
    const KickSpec& was = base.kicks[i];
    EXPECT_EQ(got.name, was.name);
    if (was.name == "side_kick_left") {
      EXPECT_DOUBLE_EQ(got.speed_mps, 0.51);
      EXPECT_DOUBLE_EQ(got.sigma_speed_mps, 0.03);
      EXPECT_DOUBLE_EQ(got.direction_rad, 1.58);
      EXPECT_DOUBLE_EQ(got.sigma_direction_rad, 0.04);
    } else {
      EXPECT_EQ(got.speed_mps, was.speed_mps) << was.name;
      EXPECT_EQ(got.sigma_speed_mps, was.sigma_speed_mps) << was.name;
      EXPECT_EQ(got.direction_rad, was.direction_rad) << was.name;
      EXPECT_EQ(got.sigma_direction_rad, was.sigma_direction_rad) << was.name;
    }
  }
  EXPECT_NO_THROW(model.Validate());
  // Without a deceleration the base's stays.
  EXPECT_EQ(ApplyCalibration(base, fits, std::nullopt).rolling_deceleration_mps2,
            base.rolling_deceleration_mps2);
}

TEST(CalibrationTest, ApplyCalibrationOfAnUnknownKickIsAnInputError) {
  const KickModel base = LoadKickModel(testing::ModelsDir() / "kicks" / "nao.json");
  const std::vector<KickCalibration> fits = {Fitted("forward", 1.0, 0.1, 0.0, 0.1),
                                             Fitted("bicycle_kick", 1.0, 0.1, 0.0, 0.1)};
  try {
    ApplyCalibration(base, fits, std::nullopt);
    FAIL() << "an unknown kick was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("bicycle_kick"));
  }
}

}  // namespace
}  // namespace foresight
