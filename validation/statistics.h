// Statistics for calibration and fidelity: distribution functions, fits with confidence
// intervals, a goodness-of-fit test valid with estimated parameters, rank agreement.
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

namespace foresight {

inline constexpr std::uint64_t kBootstrapDomain = 0x626f6f7473747270ULL;

struct Interval {
  double low = 0.0;
  double high = 0.0;
  bool Contains(double x) const { return low <= x && x <= high; }
};

// --- distribution functions ---------------------------------------------------------------
double NormalCdf(double z);
double NormalPdf(double z);
double NormalQuantile(double p);                 // Wichura, AS 241 (1988), |err| < 1e-15
double StudentTQuantile(double p, double dof);   // dof > 0
double ChiSquareQuantile(double p, double dof);  // dof > 0

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

// --- goodness of fit ------------------------------------------------------------------------
// Anderson-Darling test of normality with mean and sd estimated from the same data (Stephens'
// case 3): A*^2 = A^2 (1 + 0.75/n + 2.25/n^2), p-value from D'Agostino & Stephens (1986),
// Goodness-of-Fit Techniques, table 4.9. Also the Lilliefors (1967) Kolmogorov-Smirnov
// statistic with the Dallal & Wilkinson (1986) p-value approximation.
struct NormalityTest {
  int n = 0;
  double anderson_darling = 0.0;  // A*^2
  double anderson_darling_p = 0.0;
  double lilliefors_d = 0.0;
  double lilliefors_p = 0.0;  // capped to [0, 0.1]..1 as the approximation allows
  bool Rejected(double level) const { return anderson_darling_p < level; }
};
NormalityTest TestNormality(std::span<const double> x);  // n >= 8

// Normal QQ plot: sorted sample against N(mean, sd) quantiles at Blom's plotting positions
// (i - 3/8) / (n + 1/4), both in the data's units.
struct QqPoint {
  double theoretical = 0.0;
  double observed = 0.0;
};
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
