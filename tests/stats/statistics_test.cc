// Statistics: distribution functions against reference values (computed to 30 digits with
// mpmath from the defining integrals), fits and intervals on fixed-seed samples, the normality
// tests on a tiny hand-checkable sample, rank agreement on hand-counted cases, and input checks.
#include "stats/statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/random.h"
#include "stats/distributions.h"
#include "stats/goodness_of_fit.h"

namespace foresight {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

std::vector<double> NormalSample(std::uint64_t seed, int n, double mean, double sd) {
  RandomStream stream(StreamKey(seed, 0));
  std::vector<double> x(n);
  for (double& v : x) v = mean + sd * stream.NextNormal();
  return x;
}

std::vector<double> ExponentialSample(std::uint64_t seed, int n) {
  RandomStream stream(StreamKey(seed, 0));
  std::vector<double> x(n);
  for (double& v : x) v = -std::log1p(-stream.NextUniform());
  return x;
}

// Expects f() to throw std::invalid_argument whose message names `function`.
template <class F>
void ExpectInvalid(F f, const std::string& function) {
  try {
    (void)f();
    ADD_FAILURE() << "no exception; expected one from " << function;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(function), std::string::npos) << e.what();
  }
}

TEST(StatisticsDistributionTest, KnownValues) {
  EXPECT_NEAR(NormalQuantile(0.975), 1.959963984540054, 1e-15);
  EXPECT_NEAR(NormalCdf(1.96), 0.9750021048517796, 1e-15);
  EXPECT_NEAR(NormalPdf(0.0), 0.3989422804014327, 1e-16);
  EXPECT_NEAR(StudentTQuantile(0.975, 10), 2.2281388519862742, 1e-13);
  EXPECT_NEAR(StudentTQuantile(0.975, 1), 12.706204736174693, 1e-11);
  EXPECT_NEAR(StudentTQuantile(0.025, 3.5), -2.9400886379827288, 1e-12);
  EXPECT_NEAR(ChiSquareQuantile(0.975, 10), 20.483177350807394, 1e-12);
  EXPECT_NEAR(ChiSquareQuantile(0.025, 10), 3.2469727802368411, 1e-13);
  EXPECT_NEAR(ChiSquareQuantile(0.5, 1), 0.45493642311957275, 1e-14);
  EXPECT_NEAR(ChiSquareQuantile(0.5, 1e5) / 99999.333334123463, 1.0, 1e-12);
}

TEST(StatisticsDistributionTest, NormalQuantileRoundTripsInAllThreeRegions) {
  // The regions of AS 241: |p - 0.5| <= 0.425, then r = sqrt(-ln min(p, 1-p)) up to 5, beyond.
  for (double p : {1e-300, 1e-20, 1e-10, 1e-3, 0.02, 0.075, 0.3, 0.5, 0.7, 0.93, 0.999999}) {
    const double z = NormalQuantile(p);
    EXPECT_NEAR(NormalCdf(z) / p, 1.0, 1e-13) << "p = " << p;
    if (p >= 1e-3) {  // below, 1 - p itself is rounded too coarsely to compare
      EXPECT_NEAR(NormalQuantile(1.0 - p), -z, 1e-12) << "p = " << p;
    }
  }
  EXPECT_NEAR(NormalQuantile(1e-300), -37.047096299361199, 1e-12);
}

TEST(StatisticsDistributionTest, TAndChiSquareMatchClosedForms) {
  for (double p : {1e-9, 0.01, 0.2, 0.5, 0.8, 0.975, 1.0 - 1e-9}) {
    // t with 1 dof is Cauchy, t = -cot(pi p); with 2 dof t = (2p - 1) / sqrt(2 p (1 - p)).
    const double t1 = p < 0.5 ? -1.0 / std::tan(kPi * p) : 1.0 / std::tan(kPi * (1.0 - p));
    EXPECT_NEAR(StudentTQuantile(p, 1), t1, 1e-11 * std::max(1.0, std::abs(t1))) << p;
    const double t2 = (2.0 * p - 1.0) / std::sqrt(2.0 * p * (1.0 - p));
    EXPECT_NEAR(StudentTQuantile(p, 2), t2, 1e-11 * std::max(1.0, std::abs(t2))) << p;
    // chi-square with 2 dof is exponential with mean 2.
    EXPECT_NEAR(ChiSquareQuantile(p, 2) / (-2.0 * std::log1p(-p)), 1.0, 1e-11) << p;
  }
  for (double p : {0.01, 0.2, 0.5, 0.8, 0.975, 1.0 - 1e-9}) {
    // chi-square with 1 dof is a squared normal: P(X > x) = 2 Phi(-sqrt(x)).
    const double z = NormalQuantile(0.5 * (1.0 - p));
    EXPECT_NEAR(ChiSquareQuantile(p, 1) / (z * z), 1.0, 1e-12) << p;
  }
  EXPECT_NEAR(StudentTQuantile(0.975, 1e6), 1.9599663568141067, 1e-9);  // tends to the normal
}

TEST(StatisticsNormalFitTest, HandComputedSmallSamples) {
  const std::vector<double> x = {1, 2, 3, 4, 5};
  const NormalFit fit = FitNormal(x, 0.95);
  EXPECT_EQ(fit.n, 5);
  EXPECT_DOUBLE_EQ(fit.mean, 3.0);
  EXPECT_NEAR(fit.sd, std::sqrt(2.5), 1e-15);
  EXPECT_NEAR(fit.mean_ci.high - 3.0, 1.9632431614775577, 1e-12);  // t_4 sd / sqrt(5)
  EXPECT_NEAR(3.0 - fit.mean_ci.low, 1.9632431614775577, 1e-12);
  EXPECT_NEAR(fit.sd_ci.low, 0.94731267067522356, 1e-12);
  EXPECT_NEAR(fit.sd_ci.high, 4.5434903934482674, 1e-11);
  EXPECT_NEAR(fit.skewness, 0.0, 1e-15);
  EXPECT_NEAR(fit.excess_kurtosis, -1.3, 1e-14);  // m4 / m2^2 - 3 = 6.8 / 4 - 3
  const NormalFit skewed = FitNormal(std::vector<double>{0, 0, 0, 1}, 0.95);
  EXPECT_NEAR(skewed.skewness, 2.0 / std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(skewed.excess_kurtosis, -2.0 / 3.0, 1e-14);
}

TEST(StatisticsNormalFitTest, RecoversTruthFromLargeSample) {
  const std::vector<double> x = NormalSample(2024, 1000, 1.0, 0.15);
  const NormalFit fit = FitNormal(x, 0.95);
  EXPECT_NEAR(fit.mean, 1.0, 0.05);
  EXPECT_NEAR(fit.sd, 0.15, 0.05 * 0.15);
  EXPECT_TRUE(fit.mean_ci.Contains(1.0)) << fit.mean_ci.low << " " << fit.mean_ci.high;
  EXPECT_TRUE(fit.sd_ci.Contains(0.15)) << fit.sd_ci.low << " " << fit.sd_ci.high;
  // Four standard errors, sqrt(6/n) and sqrt(24/n): this sample's g1 = 0.23 is a 3-sigma draw.
  EXPECT_NEAR(fit.skewness, 0.0, 4.0 * std::sqrt(6.0 / 1000.0));
  EXPECT_NEAR(fit.excess_kurtosis, 0.0, 4.0 * std::sqrt(24.0 / 1000.0));
  const Interval t = MeanTInterval(x, 0.95);
  EXPECT_DOUBLE_EQ(t.low, fit.mean_ci.low);
  EXPECT_DOUBLE_EQ(t.high, fit.mean_ci.high);
}

TEST(StatisticsNormalFitTest, IntervalCoverageIsNominal) {
  int covered_mean = 0;
  for (int rep = 0; rep < 200; ++rep) {
    covered_mean += FitNormal(NormalSample(1000 + rep, 30, 1.0, 0.15), 0.95).mean_ci.Contains(1.0);
  }
  EXPECT_GE(covered_mean, 180);
  EXPECT_LE(covered_mean, 198);
  // The sd interval over more replicates, as its count scatters more: 950 +- 7 expected.
  int covered_sd = 0;
  for (int rep = 0; rep < 1000; ++rep) {
    covered_sd += FitNormal(NormalSample(3000 + rep, 30, 1.0, 0.15), 0.95).sd_ci.Contains(0.15);
  }
  EXPECT_GE(covered_sd, 920);
  EXPECT_LE(covered_sd, 980);
}

TEST(StatisticsIntervalTest, BootstrapMeanIsDeterministicAndNearTheTInterval) {
  const std::vector<double> x = NormalSample(7, 1000, 1.0, 0.15);
  const Interval a = BootstrapMeanInterval(x, 0.95, 1000, 42);
  const Interval b = BootstrapMeanInterval(x, 0.95, 1000, 42);
  const Interval c = BootstrapMeanInterval(x, 0.95, 1000, 43);
  EXPECT_EQ(a.low, b.low);
  EXPECT_EQ(a.high, b.high);
  EXPECT_NE(a.low, c.low);
  const Interval t = MeanTInterval(x, 0.95);
  const double width = t.high - t.low;
  EXPECT_NEAR(a.low, t.low, 0.15 * width);
  EXPECT_NEAR(a.high, t.high, 0.15 * width);
}

TEST(StatisticsIntervalTest, WilsonKnownValues) {
  const Interval eight = WilsonInterval(8, 10, 0.95);
  EXPECT_NEAR(eight.low, 0.4902, 5e-5);
  EXPECT_NEAR(eight.high, 0.9433, 5e-5);
  const Interval none = WilsonInterval(0, 10, 0.95);
  EXPECT_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, 0.27753279986288917, 1e-14);  // z^2 / (n + z^2)
  const Interval all = WilsonInterval(10, 10, 0.95);
  EXPECT_NEAR(all.low, 1.0 - 0.27753279986288917, 1e-14);
  EXPECT_EQ(all.high, 1.0);
}

TEST(StatisticsCircularTest, WrappedNormalStraddlingPi) {
  const double truth = 175.0 * kDeg, sigma = 10.0 * kDeg;
  RandomStream stream(StreamKey(99, 0));
  std::vector<double> angles(1000);
  int negative = 0;
  for (double& a : angles) {
    a = std::remainder(truth + sigma * stream.NextNormal(), 2.0 * kPi);
    negative += a < 0.0;
  }
  ASSERT_GT(negative, 100);  // the sample really straddles +-180 deg
  const CircularFit fit = FitCircular(angles, 0.95, 1000, 5);
  EXPECT_EQ(fit.n, 1000);
  EXPECT_GT(fit.mean_rad, -kPi);
  EXPECT_LE(fit.mean_rad, kPi);
  EXPECT_NEAR(std::remainder(fit.mean_rad - truth, 2.0 * kPi), 0.0, 1.0 * kDeg);
  EXPECT_NEAR(fit.sd_rad, sigma, 0.05 * sigma);
  EXPECT_NEAR(fit.resultant_length, std::exp(-0.5 * fit.sd_rad * fit.sd_rad), 1e-12);
  const double truth_near_mean = fit.mean_rad + std::remainder(truth - fit.mean_rad, 2.0 * kPi);
  EXPECT_TRUE(fit.mean_ci_rad.Contains(truth_near_mean))
      << fit.mean_ci_rad.low << " " << fit.mean_ci_rad.high;
  EXPECT_LT(fit.mean_ci_rad.high - fit.mean_ci_rad.low, 3.0 * kDeg);  // one interval, not 360
  EXPECT_TRUE(fit.sd_ci_rad.Contains(sigma)) << fit.sd_ci_rad.low << " " << fit.sd_ci_rad.high;
  const CircularFit again = FitCircular(angles, 0.95, 1000, 5);
  EXPECT_EQ(again.mean_ci_rad.low, fit.mean_ci_rad.low);
  EXPECT_EQ(again.sd_ci_rad.high, fit.sd_ci_rad.high);

  const std::vector<double> unwrapped = UnwrapAround(angles, fit.mean_rad);
  ASSERT_EQ(unwrapped.size(), angles.size());
  for (std::size_t i = 0; i < angles.size(); ++i) {
    EXPECT_LE(std::abs(unwrapped[i] - fit.mean_rad), kPi);
    EXPECT_NEAR(std::cos(unwrapped[i]), std::cos(angles[i]), 1e-12);
    EXPECT_NEAR(std::sin(unwrapped[i]), std::sin(angles[i]), 1e-12);
  }
  EXPECT_NEAR(UnwrapAround(std::vector<double>{-179.0 * kDeg}, truth)[0], 181.0 * kDeg, 1e-12);
}

TEST(StatisticsNormalityTest, TinySamplesMatchIndependentComputation) {
  // Reference values computed with mpmath (30 digits) straight from the definitions in
  // goodness_of_fit.cc: standardize with the n - 1 sd, z_i = Phi(w_i), A^2, A*^2 = A^2 (1 +
  // 0.75/n + 2.25/n^2), the table 4.9 branch, D = max(i/n - z_i, z_i - (i-1)/n).
  // Symmetric sample, mean 4.2375, sd 1.566559: A*^2 = 0.164988 falls in the first branch; the
  // Dallal-Wilkinson value 1.47 is clamped to 1.
  const NormalityTest a =
      TestNormality(std::vector<double>{2.1, 2.9, 3.4, 3.8, 4.2, 4.9, 5.6, 7.0});
  EXPECT_EQ(a.n, 8);
  EXPECT_NEAR(a.anderson_darling, 0.164987710644519, 1e-12);
  EXPECT_NEAR(a.anderson_darling_p, 0.941532538608958, 1e-12);
  EXPECT_NEAR(a.lilliefors_d, 0.134548894583163, 1e-12);
  EXPECT_EQ(a.lilliefors_p, 1.0);
  // Skewed sample, mean 1.73, sd 1.683284: A^2 = 1.077173, A*^2 = 1.182197 in the last branch.
  const NormalityTest b =
      TestNormality(std::vector<double>{0.5, 0.6, 0.7, 0.8, 1.0, 1.2, 1.5, 2.0, 3.0, 6.0});
  EXPECT_NEAR(b.anderson_darling, 1.18219694181614, 1e-12);
  EXPECT_NEAR(b.anderson_darling_p, 0.00438543185194847, 1e-14);
  EXPECT_NEAR(b.lilliefors_d, 0.254341404967851, 1e-12);
  EXPECT_NEAR(b.lilliefors_p, 0.0659067609841446, 1e-12);
  EXPECT_TRUE(b.Rejected(0.01));
  EXPECT_FALSE(a.Rejected(0.05));
}

TEST(StatisticsNormalityTest, EqualValuesHaveNoTestAndRejectNothing) {
  const NormalityTest t = TestNormality(std::vector<double>(12, 3.5));
  EXPECT_TRUE(t.all_equal);
  EXPECT_EQ(t.n, 12);
  EXPECT_TRUE(std::isnan(t.anderson_darling_p));
  EXPECT_FALSE(t.Rejected(0.05));
  EXPECT_FALSE(TestNormality(std::vector<double>{1, 1, 1, 1, 1, 1, 1, 1.0000001}).all_equal);
}

TEST(StatisticsNormalityTest, NormalSamplesAreNotRejected) {
  for (std::uint64_t seed : {1, 2, 3, 4, 5}) {
    const NormalityTest t = TestNormality(NormalSample(seed, 200, 1.0, 0.15));
    EXPECT_FALSE(t.Rejected(0.01)) << "seed " << seed << " A*2 " << t.anderson_darling;
    EXPECT_GT(t.lilliefors_p, 0.01) << "seed " << seed;
  }
}

TEST(StatisticsNormalityTest, SkewedSamplesAreRejected) {
  const NormalityTest exponential = TestNormality(ExponentialSample(11, 200));
  EXPECT_LT(exponential.anderson_darling_p, 0.01);
  EXPECT_LT(exponential.lilliefors_p, 0.01);
  std::vector<double> lognormal = NormalSample(12, 200, 0.0, 0.8);
  for (double& v : lognormal) v = std::exp(v);
  EXPECT_LT(TestNormality(lognormal).anderson_darling_p, 0.01);
}

TEST(StatisticsNormalityTest, RejectionRateUnderTheNullIsNominal) {
  // Checks the case-3 modification and p formula together: 5 % of normal samples rejected.
  int rejected_ad = 0, rejected_lf = 0;
  for (int rep = 0; rep < 400; ++rep) {
    const NormalityTest t = TestNormality(NormalSample(5000 + rep, 50, 3.0, 2.0));
    rejected_ad += t.Rejected(0.05);
    rejected_lf += t.lilliefors_p < 0.05;
  }
  EXPECT_GE(rejected_ad, 8);
  EXPECT_LE(rejected_ad, 36);
  EXPECT_GE(rejected_lf, 8);
  EXPECT_LE(rejected_lf, 36);
}

TEST(StatisticsQqTest, BlomPositionsForFourPoints) {
  const std::vector<QqPoint> qq = NormalQq(std::vector<double>{12.5, 8.0, 10.5, 9.0}, 10.0, 2.0);
  ASSERT_EQ(qq.size(), 4u);
  // 10 + 2 Phi^-1((i - 3/8) / 4.25) for i = 1..4 (mpmath).
  const double expected[4] = {7.9017372040720576, 9.4013861790686660, 10.598613820931334,
                              12.098262795927942};
  const double observed[4] = {8.0, 9.0, 10.5, 12.5};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(qq[i].theoretical, expected[i], 1e-13);
    EXPECT_EQ(qq[i].observed, observed[i]);
  }
  EXPECT_TRUE(NormalQq(std::vector<double>{}, 0.0, 1.0).empty());
}

TEST(StatisticsKendallTest, HandCountedCases) {
  // Pairs of {1,2,2,3} vs {1,3,2,2}: C = 3, D = 1, one pair tied in each: 2 / sqrt(5 * 5).
  EXPECT_NEAR(KendallTauB(std::vector<double>{1, 2, 2, 3}, std::vector<double>{1, 3, 2, 2}), 0.4,
              1e-15);
  // Ties only in b: all 8 untied pairs concordant, 10 untied in a: 8 / sqrt(80).
  EXPECT_NEAR(KendallTauB(std::vector<double>{1, 2, 3, 4, 5}, std::vector<double>{1, 1, 2, 2, 3}),
              2.0 / std::sqrt(5.0), 1e-15);
  const std::vector<double> up = {0.1, 0.5, 0.7, 2.0, 3.0};
  const std::vector<double> same_order = {1, 2, 3, 40, 50};
  const std::vector<double> reversed = {5, 4, 3, 2, 1};
  const std::vector<double> constant = {7, 7, 7, 7, 7};
  EXPECT_DOUBLE_EQ(KendallTauB(up, same_order), 1.0);
  EXPECT_DOUBLE_EQ(KendallTauB(up, reversed), -1.0);
  EXPECT_EQ(KendallTauB(up, constant), 0.0);
  EXPECT_EQ(KendallTauB(constant, up), 0.0);
}

TEST(StatisticsInvalidInputTest, ThrowsNamingTheFunction) {
  const double nan = std::nan("");
  const std::vector<double> two = {1.0, 2.0};
  const std::vector<double> with_nan = {1.0, 2.0, nan, 4.0};
  ExpectInvalid([] { return NormalQuantile(0.0); }, "NormalQuantile");
  ExpectInvalid([] { return NormalQuantile(1.0); }, "NormalQuantile");
  ExpectInvalid([&] { return NormalQuantile(nan); }, "NormalQuantile");
  ExpectInvalid([] { return StudentTQuantile(1.2, 3); }, "StudentTQuantile");
  ExpectInvalid([] { return StudentTQuantile(0.5, 0); }, "StudentTQuantile");
  ExpectInvalid([] { return ChiSquareQuantile(0.5, -1); }, "ChiSquareQuantile");
  ExpectInvalid([&] { return ChiSquareQuantile(nan, 3); }, "ChiSquareQuantile");
  ExpectInvalid([&] { return FitNormal(two, 0.95); }, "FitNormal");
  ExpectInvalid([&] { return FitNormal(with_nan, 0.95); }, "FitNormal");
  ExpectInvalid([&] { return FitNormal(std::vector<double>{1, 2, 3}, 1.0); }, "FitNormal");
  ExpectInvalid([&] { return FitCircular(two, 0.95, 100, 1); }, "FitCircular");
  ExpectInvalid(
      [&] {
        return FitCircular(std::vector<double>{1, 2, 3}, 0.95, 1, 1);
      },
      "FitCircular");
  ExpectInvalid([&] { return UnwrapAround(with_nan, 0.0); }, "UnwrapAround");
  ExpectInvalid([&] { return TestNormality(std::vector<double>(7, 1.0)); }, "TestNormality");
  ExpectInvalid([&] { return NormalQq(two, 0.0, -1.0); }, "NormalQq");
  ExpectInvalid([&] { return BootstrapMeanInterval(with_nan, 0.95, 100, 1); },
                "BootstrapMeanInterval");
  ExpectInvalid([&] { return MeanTInterval(std::vector<double>{1.0}, 0.95); }, "MeanTInterval");
  ExpectInvalid([] { return WilsonInterval(11, 10, 0.95); }, "WilsonInterval");
  ExpectInvalid([] { return WilsonInterval(0, 0, 0.95); }, "WilsonInterval");
  ExpectInvalid([&] { return KendallTauB(two, with_nan); }, "KendallTauB");
  ExpectInvalid([&] { return KendallTauB(with_nan, with_nan); }, "KendallTauB");
}

TEST(SummaryTest, MeanSdIsTwoPassAndStableFarFromZero) {
  // A sum of squares would lose every digit of this sd at an offset of 1e9.
  const std::vector<double> x = {1e9 + 1.0, 1e9 + 2.0, 1e9 + 3.0};
  const MeanSd s = SampleMeanSd(x);
  EXPECT_DOUBLE_EQ(s.mean, 1e9 + 2.0);
  EXPECT_DOUBLE_EQ(s.sd, 1.0);
  EXPECT_EQ(SampleMeanSd(std::vector<double>{4.0}).sd, 0.0);
  EXPECT_EQ(SampleMeanSd(std::vector<double>{}).mean, 0.0);
}

TEST(SummaryTest, CircularSummaryWrapsAndMatchesTheFit) {
  const std::vector<double> angles = {std::numbers::pi - 0.1, -std::numbers::pi + 0.1,
                                      std::numbers::pi - 0.05, -std::numbers::pi + 0.05};
  const CircularSummary s = SummarizeCircular(angles);
  EXPECT_NEAR(std::abs(s.mean_rad), std::numbers::pi, 1e-12);
  const CircularFit fit = FitCircular(angles, 0.95, 100, 1);
  EXPECT_EQ(s.mean_rad, fit.mean_rad);
  EXPECT_EQ(s.sd_rad, fit.sd_rad);
  EXPECT_EQ(s.resultant_length, fit.resultant_length);
  EXPECT_EQ(SummarizeCircular(std::vector<double>{}).sd_rad, 0.0);
}

}  // namespace
}  // namespace foresight

namespace foresight {
namespace {

TEST(RobustSdTest, ExactOnASmallSampleAndDeafToAnOutlier) {
  // Median 3, absolute deviations {2, 1, 0, 1, 2}: MAD 1, so 1.4826.
  EXPECT_DOUBLE_EQ(RobustSd(std::vector<double>{1, 2, 3, 4, 5}), 1.4826);
  // One wild value barely moves it (the sample sd jumps from 1.6 to 44).
  EXPECT_DOUBLE_EQ(RobustSd(std::vector<double>{1, 2, 3, 4, 100}), 1.4826);
  EXPECT_EQ(RobustSd(std::vector<double>{7}), 0.0);
}

TEST(RobustSdTest, EstimatesTheSdOfNormalDraws) {
  RandomStream stream(StreamKey(3, 0, 0));
  std::vector<double> x(20000);
  for (double& v : x) v = 2.5 * stream.NextNormal();
  EXPECT_NEAR(RobustSd(x), 2.5, 0.06);  // the MAD's sampling sd here is about 0.02
}

}  // namespace
}  // namespace foresight
