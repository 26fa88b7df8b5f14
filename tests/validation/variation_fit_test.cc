// Fitting the physical causes of the spread: a synthetic log drawn in physics from known
// magnitudes of the causes is fitted back to those magnitudes.
#include "validation/variation_fit.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/model_test_util.h"
#include "tests/support/temp_files.h"
#include "validation/physics_calibration.h"

namespace foresight {
namespace {

constexpr int kTrials = 200;

// The "real robot": physics with the true magnitudes and seeds the fit never uses.
std::map<std::string, LaunchSpread> SyntheticLog(const TrialVariation& truth) {
  std::map<std::string, LaunchSpread> log;
  for (const char* kick : {"side_kick_left"}) {
    PhysicsCalibrationSettings s;
    s.robot = "nao";
    s.kick = kick;
    s.trials = kTrials;
    s.seed = 4242;
    s.threads = 2;
    // The fixed base, the cheap approximation, for the "real robot" and the fit alike.
    s.base = RobotBase::kFixed;
    s.variation = truth;
    log[kick] = SpreadOf(RunPhysicsCalibration(s, testing::ModelsDir()).kicks.front().observations);
  }
  return log;
}

TEST(VariationFitTest, RecoversTheMagnitudesALogWasDrawnWith) {
  const TrialVariation base = LoadRobot("nao", testing::ModelsDir()).spec.variation;
  // Chosen so both groups show in the log: placement sets the direction's spread, the playback
  // speed most of the speed's. (A log whose speed spread placement alone explains cannot tell
  // the playback spread apart: the fit then puts it near 0, and says so in its residual.) The
  // log is of the side kick: the forward pendulum strike (issue 12, second pass) loses speed
  // when the ball lies 2-3 cm farther than planned, so placement explains most of its speed
  // spread too (fitted on it, the residual is 0.20).
  const std::map<std::string, LaunchSpread> log = SyntheticLog(ScaledVariation(base, 0.6, 0.9));
  VariationFitSettings settings;
  settings.robot = "nao";
  settings.trials = kTrials;
  settings.threads = 2;
  settings.base = RobotBase::kFixed;  // as the log's
  const VariationFit fit = FitVariation(settings, log, testing::ModelsDir());
  // A 200-trial robust sd has a sampling error of about 8 %; the fit reads two of them.
  EXPECT_NEAR(fit.placement_scale, 0.6, 0.12);
  EXPECT_NEAR(fit.playback_scale, 0.9, 0.15);
  EXPECT_FALSE(fit.playback_at_limit);
  EXPECT_LT(fit.rms_residual_rel, 0.15);
  EXPECT_DOUBLE_EQ(fit.fitted.placement_sigma_x_m, base.placement_sigma_x_m * fit.placement_scale);
  ASSERT_EQ(fit.kicks.size(), 1u);
  EXPECT_GT(fit.fastest_playback, 1.0);
}

TEST(VariationFitTest, APlaybackSpreadPastTheJointLimitsIsHeldAtTheLimit) {
  // A speed spread this large would need a playback sigma that drives the hip past its limit.
  std::map<std::string, LaunchSpread> log = {{"forward", {0.5, 3.0 * kDegToRad}}};
  VariationFitSettings settings;
  settings.robot = "nao";
  settings.trials = 50;
  settings.threads = 2;
  settings.base = RobotBase::kFixed;  // the cheap approximation: the limit is the motion's
  const VariationFit fit = FitVariation(settings, log, testing::ModelsDir());
  EXPECT_TRUE(fit.playback_at_limit);
  EXPECT_NEAR(fit.fitted.MaxSpeedFactor(), fit.fastest_playback, 1e-9);
  EXPECT_GT(fit.rms_residual_rel, 0.3);  // and it says so: the speed spread is not reproduced
}

}  // namespace
}  // namespace foresight
