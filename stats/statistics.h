// Statistics for calibration and fidelity: fits with confidence intervals, quantiles and
// intervals, rank agreement. Distribution functions are in stats/distributions.h, normality
// tests in stats/goodness_of_fit.h; the conventions below hold for all three.
//
// Conventions: `confidence` is the two-sided level in (0, 1), e.g. 0.95. Bootstrap intervals are
// percentile intervals over `resamples` resamples drawn from RandomStream(StreamKey(seed, r,
// kBootstrapDomain)) for resample r, so they are deterministic and independent of threads.
// Functions throw std::invalid_argument on inputs they cannot handle (too few values, p outside
// (0, 1), non-finite values); callers turn that into a user-facing error where needed.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/quantile.h"

namespace foresight {

inline constexpr std::uint64_t kBootstrapDomain = 0x626f6f7473747270ULL;

struct Interval {
  double low = 0.0;
  double high = 0.0;
  bool Contains(double x) const { return low <= x && x <= high; }
};

// --- summaries without intervals ------------------------------------------------------------
// Mean and sample standard deviation (n - 1), in two passes (sum of squared deviations from the
// mean), so values far from 0 lose no precision. No values: {0, 0}; one value: sd 0.
struct MeanSd {
  double mean = 0.0;
  double sd = 0.0;
};
MeanSd SampleMeanSd(std::span<const double> x);

// A spread that outliers do not move: the median absolute deviation from the median times
// 1.4826, which estimates a normal's sd (Rousseeuw & Croux, "Alternatives to the median absolute
// deviation", JASA 88 (1993) 1273-1283). Fewer than two values: 0.
double RobustSd(std::span<const double> x);

// Circular mean atan2(sum sin, sum cos) in (-pi, pi], mean resultant length R in [0, 1] and
// circular standard deviation sqrt(-2 ln R) (infinite for R = 0). No angles: all 0.
struct CircularSummary {
  double mean_rad = 0.0;
  double resultant_length = 0.0;
  double sd_rad = 0.0;
};
CircularSummary SummarizeCircular(std::span<const double> angles_rad);

// --- normal model (speeds) ------------------------------------------------------------------
struct NormalFit {
  int n = 0;
  double mean = 0.0;
  double sd = 0.0;               // sample standard deviation (n - 1)
  Interval mean_ci;              // exact: mean +- t_{n-1} sd / sqrt(n)
  Interval sd_ci;                // exact: sd * sqrt((n-1) / chi2_{n-1}) at both tails
  double skewness = 0.0;         // sample skewness g1
  double excess_kurtosis = 0.0;  // sample excess kurtosis g2
};
NormalFit FitNormal(std::span<const double> x, double confidence);  // n >= 3

// --- circular model (directions) ------------------------------------------------------------
struct CircularFit {
  int n = 0;
  double mean_rad = 0.0;          // circular mean atan2(sum sin, sum cos), in (-pi, pi]
  double resultant_length = 0.0;  // mean resultant length R in [0, 1]
  double sd_rad = 0.0;            // circular standard deviation sqrt(-2 ln R)
  Interval mean_ci_rad;           // bootstrap; expressed around mean_rad (may leave (-pi, pi])
  Interval sd_ci_rad;             // bootstrap
};
CircularFit FitCircular(std::span<const double> angles_rad, double confidence, int resamples,
                        std::uint64_t seed);  // n >= 3

// The angles unwrapped to mean_rad +- pi, for histograms and normal tests of directions.
std::vector<double> UnwrapAround(std::span<const double> angles_rad, double centre_rad);

// Normal QQ plot: sorted sample against N(mean, sd) quantiles at Blom's plotting positions
// (i - 3/8) / (n + 1/4), both in the data's units.
std::vector<QqPoint> NormalQq(std::span<const double> x, double mean, double sd);

// --- intervals ------------------------------------------------------------------------------
// The central `confidence` share of `values` (e.g. bootstrap estimates): quantiles with linear
// interpolation between order statistics (Hyndman & Fan type 7). `values` must not be empty.
Interval PercentileInterval(std::vector<double> values, double confidence);
Interval BootstrapMeanInterval(std::span<const double> x, double confidence, int resamples,
                               std::uint64_t seed);
Interval MeanTInterval(std::span<const double> x, double confidence);  // n >= 2
Interval WilsonInterval(int successes, int n, double confidence);      // n >= 1

// --- rank agreement -------------------------------------------------------------------------
// Kendall's tau-b between two scorings of the same items (ties handled as in Kendall 1945):
// (C - D) / sqrt((n0 - n1)(n0 - n2)). Returns 0 when either scoring is constant.
double KendallTauB(std::span<const double> a, std::span<const double> b);

}  // namespace foresight
