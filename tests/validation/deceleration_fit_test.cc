// The pooled deceleration fit on synthetic rolling trials v = v_i - a t with known a.
#include "validation/deceleration_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/random.h"

namespace foresight {
namespace {

constexpr double kTruth = 0.27;  // m/s^2

// Trial i starts at its own time and speed; samples every 0.1 s with speed noise `noise_sd`.
std::vector<SpeedSample> Trial(int i, double deceleration, double noise_sd, int samples = 25) {
  const double v0[] = {1.0, 1.5, 2.0, 2.5, 3.0, 1.8, 2.2, 1.2};
  const double t0[] = {0.0, 0.3, 1.2, 0.7, 2.0, 0.1, 5.0, 0.45};
  RandomStream stream(StreamKey(77, static_cast<std::uint64_t>(i)));
  std::vector<SpeedSample> trial(samples);
  for (int j = 0; j < samples; ++j) {
    const double t = t0[i % 8] + 0.1 * j;
    trial[j] = {t, v0[i % 8] - deceleration * t + noise_sd * stream.NextNormal()};
  }
  return trial;
}

std::vector<std::vector<SpeedSample>> Trials(int count, double noise_sd) {
  std::vector<std::vector<SpeedSample>> trials;
  for (int i = 0; i < count; ++i) trials.push_back(Trial(i, kTruth, noise_sd));
  return trials;
}

TEST(DecelerationFitTest, RecoversCommonSlopeAcrossTrials) {
  const auto trials = Trials(8, 0.005);
  const DecelerationFit fit = FitDeceleration(trials, 0.95, 2000, 3);
  EXPECT_EQ(fit.trials, 8);
  EXPECT_EQ(fit.samples, 200);
  EXPECT_NEAR(fit.deceleration_mps2, kTruth, 0.01 * kTruth);
  EXPECT_TRUE(fit.ci_mps2.Contains(kTruth)) << fit.ci_mps2.low << " " << fit.ci_mps2.high;
  EXPECT_LT(fit.ci_mps2.low, fit.deceleration_mps2);
  EXPECT_GT(fit.ci_mps2.high, fit.deceleration_mps2);
  EXPECT_NEAR(fit.residual_sd_mps, 0.005, 0.001);
}

TEST(DecelerationFitTest, ExactDataGivesExactSlope) {
  const DecelerationFit fit = FitDeceleration(Trials(3, 0.0), 0.95, 100, 1);
  EXPECT_NEAR(fit.deceleration_mps2, kTruth, 1e-12);
  EXPECT_NEAR(fit.ci_mps2.low, kTruth, 1e-12);
  EXPECT_NEAR(fit.ci_mps2.high, kTruth, 1e-12);
  EXPECT_NEAR(fit.residual_sd_mps, 0.0, 1e-12);
}

TEST(DecelerationFitTest, ShortAndInstantTrialsAreSkipped) {
  auto trials = Trials(6, 0.005);
  const DecelerationFit clean = FitDeceleration(trials, 0.95, 500, 9);
  // Two samples with a wild slope, and three samples all at one time: neither carries a slope.
  trials.push_back({{0.0, 3.0}, {0.1, 1.0}});
  trials.push_back({{1.0, 2.0}, {1.0, 5.0}, {1.0, 0.5}});
  trials.push_back({});
  const DecelerationFit fit = FitDeceleration(trials, 0.95, 500, 9);
  EXPECT_EQ(fit.trials, 6);
  EXPECT_EQ(fit.samples, 150);
  EXPECT_EQ(fit.deceleration_mps2, clean.deceleration_mps2);
  EXPECT_EQ(fit.ci_mps2.low, clean.ci_mps2.low);
  EXPECT_EQ(fit.ci_mps2.high, clean.ci_mps2.high);
}

TEST(DecelerationFitTest, SameSeedSameIntervalOtherSeedOther) {
  const auto trials = Trials(8, 0.005);
  const DecelerationFit a = FitDeceleration(trials, 0.95, 1000, 21);
  const DecelerationFit b = FitDeceleration(trials, 0.95, 1000, 21);
  const DecelerationFit c = FitDeceleration(trials, 0.95, 1000, 22);
  EXPECT_EQ(a.ci_mps2.low, b.ci_mps2.low);
  EXPECT_EQ(a.ci_mps2.high, b.ci_mps2.high);
  EXPECT_TRUE(a.ci_mps2.low != c.ci_mps2.low || a.ci_mps2.high != c.ci_mps2.high);
}

TEST(DecelerationFitTest, IntervalReflectsTrialToTrialVariation) {
  // Carpets differ: decelerations 0.25 and 0.29 alternate, no speed noise. Resampling whole
  // trials must show that spread (sd of the mean of 8 about 0.02 / sqrt(8) = 0.007).
  std::vector<std::vector<SpeedSample>> trials;
  for (int i = 0; i < 8; ++i) trials.push_back(Trial(i, i % 2 == 0 ? 0.25 : 0.29, 0.0));
  const DecelerationFit fit = FitDeceleration(trials, 0.95, 2000, 4);
  EXPECT_NEAR(fit.deceleration_mps2, kTruth, 1e-9);
  EXPECT_TRUE(fit.ci_mps2.Contains(kTruth));
  EXPECT_GT(fit.ci_mps2.high - fit.ci_mps2.low, 0.015);
  EXPECT_LT(fit.ci_mps2.high - fit.ci_mps2.low, 0.06);
}

TEST(DecelerationFitTest, InvalidInputThrowsNamingTheFunction) {
  const auto expect_invalid = [](std::span<const std::vector<SpeedSample>> trials,
                                 double confidence, int resamples) {
    try {
      FitDeceleration(trials, confidence, resamples, 1);
      ADD_FAILURE() << "no exception";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("FitDeceleration"), std::string::npos) << e.what();
    }
  };
  auto one = Trials(1, 0.005);
  one.push_back({{0.0, 2.0}, {0.1, 1.9}});  // a second trial, but too short to count
  expect_invalid(one, 0.95, 100);
  expect_invalid({}, 0.95, 100);
  const auto two = Trials(2, 0.005);
  expect_invalid(two, 1.5, 100);
  expect_invalid(two, 0.95, 0);
  auto with_nan = two;
  with_nan[1][3].speed_mps = std::nan("");
  expect_invalid(with_nan, 0.95, 100);
}

}  // namespace
}  // namespace foresight
