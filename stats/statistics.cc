// Fits with confidence intervals, plotting positions and rank agreement of stats/statistics.h.
//
// Formulas and sources:
//   Moments          mean, sd with divisor n - 1; skewness g1 = m3 / m2^(3/2) and excess
//                    kurtosis g2 = m4 / m2^2 - 3 with m_k = sum (x - mean)^k / n (Joanes & Gill,
//                    "Comparing measures of sample skewness and kurtosis", JRSS D 47 (1998)).
//   Mean interval    mean +- t_{n-1}((1 + c) / 2) sd / sqrt(n) (Student 1908).
//   Sd interval      (n - 1) s^2 / sigma^2 ~ chi2_{n-1}, hence
//                    [s sqrt((n-1) / chi2_{n-1}((1+c)/2)), s sqrt((n-1) / chi2_{n-1}((1-c)/2))].
//   Circular         C = sum cos, S = sum sin, mean = atan2(S, C), R = sqrt(C^2 + S^2) / n,
//                    circular sd = sqrt(-2 ln R) (Mardia & Jupp, Directional Statistics, 2000,
//                    section 2.3); it equals sigma for a wrapped normal.
//   Bootstrap        percentile interval [q((1-c)/2), q((1+c)/2)] of the resampled statistic
//                    (Efron & Tibshirani, An Introduction to the Bootstrap, 1993, ch. 13), with
//                    quantiles interpolated linearly between order statistics (Hyndman & Fan 1996,
//                    type 7). Resample r draws from RandomStream(StreamKey(seed, r,
//                    kBootstrapDomain)) only.
//   Wilson interval  (p + z^2/(2n) +- z sqrt(p(1-p)/n + z^2/(4n^2))) / (1 + z^2/n), p = k/n,
//                    z = Phi^-1((1 + c) / 2) (Wilson, JASA 22 (1927) 209-212).
//   Blom positions   (i - 3/8) / (n + 1/4), i = 1..n (Blom, Statistical Estimates and
//                    Transformed Beta-Variables, 1958).
//   Kendall tau-b    (C - D) / sqrt((n0 - n1)(n0 - n2)) (Kendall, Biometrika 33 (1945) 239-251);
//                    n0 - n1 is simply the number of pairs not tied in a, so the pairs are counted
//                    directly in O(n^2), which is ample for scorings of a few thousand items.
#include "stats/statistics.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/quantile.h"
#include "common/random.h"
#include "stats/distributions.h"

namespace foresight {
namespace {

[[noreturn]] void Fail(const char* function, const std::string& what) {
  throw std::invalid_argument(std::string(function) + ": " + what);
}

void CheckCount(const char* function, std::size_t n, std::size_t at_least) {
  if (n < at_least) {
    Fail(function,
         "need at least " + std::to_string(at_least) + " values, got " + std::to_string(n));
  }
}

void CheckFinite(const char* function, std::span<const double> x) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) Fail(function, "non-finite value at index " + std::to_string(i));
  }
}

void CheckConfidence(const char* function, double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0)) {
    Fail(function, "confidence must be in (0, 1), got " + std::to_string(confidence));
  }
}

void CheckResamples(const char* function, int resamples) {
  if (resamples < 2) Fail(function, "need at least 2 resamples, got " + std::to_string(resamples));
}

// An index uniform on [0, n), from resample r's own stream.
std::size_t DrawIndex(RandomStream& stream, std::size_t n) {
  return std::min(n - 1, static_cast<std::size_t>(stream.NextUniform() * static_cast<double>(n)));
}

double Mean(std::span<const double> x) {
  double sum = 0.0;
  for (double v : x) sum += v;
  return sum / static_cast<double>(x.size());
}

// Circular mean in (-pi, pi] and mean resultant length in [0, 1] from the sums of cos and sin.
struct Resultant {
  double mean_rad;
  double length;
};

Resultant FromSums(double cos_sum, double sin_sum, std::size_t n) {
  double mean = std::atan2(sin_sum, cos_sum);
  if (mean == -std::numbers::pi) mean = std::numbers::pi;  // atan2(-0, -1) is -pi
  return {mean, std::min(1.0, std::hypot(cos_sum, sin_sum) / static_cast<double>(n))};
}

double CircularSd(double resultant_length) {
  return std::sqrt(-2.0 * std::log(resultant_length));
}

}  // namespace

MeanSd SampleMeanSd(std::span<const double> x) {
  if (x.empty()) return {};
  MeanSd s;
  s.mean = Mean(x);
  if (x.size() < 2) return s;
  double m2 = 0.0;
  for (double v : x) m2 += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(m2 / (static_cast<double>(x.size()) - 1.0));
  return s;
}

double RobustSd(std::span<const double> x) {
  if (x.size() < 2) return 0.0;
  constexpr double kNormalConsistency = 1.4826;  // 1 / Phi^-1(3/4)
  std::vector<double> sorted(x.begin(), x.end());
  std::sort(sorted.begin(), sorted.end());
  const double median = QuantileOfSorted(sorted, 0.5);
  for (double& v : sorted) v = std::abs(v - median);
  std::sort(sorted.begin(), sorted.end());
  return kNormalConsistency * QuantileOfSorted(sorted, 0.5);
}

CircularSummary SummarizeCircular(std::span<const double> angles_rad) {
  if (angles_rad.empty()) return {};
  double cos_sum = 0.0, sin_sum = 0.0;
  for (double a : angles_rad) {
    cos_sum += std::cos(a);
    sin_sum += std::sin(a);
  }
  const Resultant all = FromSums(cos_sum, sin_sum, angles_rad.size());
  return {all.mean_rad, all.length, CircularSd(all.length)};
}

Interval PercentileInterval(std::vector<double> values, double confidence) {
  std::sort(values.begin(), values.end());
  const double alpha = 1.0 - confidence;
  return {QuantileOfSorted(values, 0.5 * alpha), QuantileOfSorted(values, 1.0 - 0.5 * alpha)};
}

NormalFit FitNormal(std::span<const double> x, double confidence) {
  CheckCount("FitNormal", x.size(), 3);
  CheckFinite("FitNormal", x);
  CheckConfidence("FitNormal", confidence);
  NormalFit fit;
  fit.n = static_cast<int>(x.size());
  const double n = static_cast<double>(x.size());
  const MeanSd mean_sd = SampleMeanSd(x);
  fit.mean = mean_sd.mean;
  fit.sd = mean_sd.sd;
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;  // two-pass central moments, accurate for any offset
  for (double v : x) {
    const double d = v - fit.mean, d2 = d * d;
    m2 += d2;
    m3 += d2 * d;
    m4 += d2 * d2;
  }
  m2 /= n;
  m3 /= n;
  m4 /= n;
  if (m2 > 0.0) {  // a constant sample has no shape; skewness and kurtosis stay 0
    fit.skewness = m3 / std::pow(m2, 1.5);
    fit.excess_kurtosis = m4 / (m2 * m2) - 3.0;
  }
  const double upper = 0.5 * (1.0 + confidence), lower = 0.5 * (1.0 - confidence);
  const double half = StudentTQuantile(upper, n - 1.0) * fit.sd / std::sqrt(n);
  fit.mean_ci = {fit.mean - half, fit.mean + half};
  fit.sd_ci = {fit.sd * std::sqrt((n - 1.0) / ChiSquareQuantile(upper, n - 1.0)),
               fit.sd * std::sqrt((n - 1.0) / ChiSquareQuantile(lower, n - 1.0))};
  return fit;
}

CircularFit FitCircular(std::span<const double> angles_rad, double confidence, int resamples,
                        std::uint64_t seed) {
  CheckCount("FitCircular", angles_rad.size(), 3);
  CheckFinite("FitCircular", angles_rad);
  CheckConfidence("FitCircular", confidence);
  CheckResamples("FitCircular", resamples);
  const std::size_t n = angles_rad.size();
  CircularFit fit;
  fit.n = static_cast<int>(n);
  const CircularSummary all = SummarizeCircular(angles_rad);
  fit.mean_rad = all.mean_rad;
  fit.resultant_length = all.resultant_length;
  fit.sd_rad = all.sd_rad;
  // The bootstrap resamples the cosines and sines rather than the angles.
  std::vector<double> cosines(n), sines(n);
  for (std::size_t i = 0; i < n; ++i) {
    cosines[i] = std::cos(angles_rad[i]);
    sines[i] = std::sin(angles_rad[i]);
  }
  std::vector<double> means(resamples), sds(resamples);
  for (int r = 0; r < resamples; ++r) {
    RandomStream stream(StreamKey(seed, static_cast<std::uint64_t>(r), kBootstrapDomain));
    double c = 0.0, s = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t i = DrawIndex(stream, n);
      c += cosines[i];
      s += sines[i];
    }
    const Resultant one = FromSums(c, s, n);
    // Around the full-sample mean, so an interval straddling +-pi stays one interval.
    means[r] = fit.mean_rad + std::remainder(one.mean_rad - fit.mean_rad, 2.0 * std::numbers::pi);
    sds[r] = CircularSd(one.length);
  }
  fit.mean_ci_rad = PercentileInterval(std::move(means), confidence);
  fit.sd_ci_rad = PercentileInterval(std::move(sds), confidence);
  return fit;
}

std::vector<double> UnwrapAround(std::span<const double> angles_rad, double centre_rad) {
  CheckFinite("UnwrapAround", angles_rad);
  if (!std::isfinite(centre_rad)) Fail("UnwrapAround", "non-finite centre");
  std::vector<double> out;
  out.reserve(angles_rad.size());
  for (double a : angles_rad) {
    // remainder() lands in [-pi, pi]; clamp guards the last bit of rounding in the sum.
    const double offset = std::remainder(a - centre_rad, 2.0 * std::numbers::pi);
    out.push_back(centre_rad + std::clamp(offset, -std::numbers::pi, std::numbers::pi));
  }
  return out;
}

std::vector<QqPoint> NormalQq(std::span<const double> x, double mean, double sd) {
  CheckFinite("NormalQq", x);
  if (!std::isfinite(mean) || !(sd >= 0.0 && std::isfinite(sd))) {
    Fail("NormalQq", "mean must be finite and sd finite and non-negative");
  }
  std::vector<double> sorted(x.begin(), x.end());
  std::sort(sorted.begin(), sorted.end());
  const double n = static_cast<double>(sorted.size());
  std::vector<QqPoint> points(sorted.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const double position = (static_cast<double>(i + 1) - 0.375) / (n + 0.25);
    points[i] = {mean + sd * NormalQuantile(position), sorted[i]};
  }
  return points;
}

Interval BootstrapMeanInterval(std::span<const double> x, double confidence, int resamples,
                               std::uint64_t seed) {
  CheckCount("BootstrapMeanInterval", x.size(), 2);
  CheckFinite("BootstrapMeanInterval", x);
  CheckConfidence("BootstrapMeanInterval", confidence);
  CheckResamples("BootstrapMeanInterval", resamples);
  const std::size_t n = x.size();
  std::vector<double> means(resamples);
  for (int r = 0; r < resamples; ++r) {
    RandomStream stream(StreamKey(seed, static_cast<std::uint64_t>(r), kBootstrapDomain));
    double sum = 0.0;
    for (std::size_t j = 0; j < n; ++j) sum += x[DrawIndex(stream, n)];
    means[r] = sum / static_cast<double>(n);
  }
  return PercentileInterval(std::move(means), confidence);
}

Interval MeanTInterval(std::span<const double> x, double confidence) {
  CheckCount("MeanTInterval", x.size(), 2);
  CheckFinite("MeanTInterval", x);
  CheckConfidence("MeanTInterval", confidence);
  const double n = static_cast<double>(x.size());
  const double mean = Mean(x);
  double ss = 0.0;
  for (double v : x) ss += (v - mean) * (v - mean);
  const double half =
      StudentTQuantile(0.5 * (1.0 + confidence), n - 1.0) * std::sqrt(ss / (n - 1.0) / n);
  return {mean - half, mean + half};
}

Interval WilsonInterval(int successes, int n, double confidence) {
  if (n < 1) Fail("WilsonInterval", "need n >= 1, got " + std::to_string(n));
  if (successes < 0 || successes > n) {
    Fail("WilsonInterval", "successes must be in [0, n], got " + std::to_string(successes));
  }
  CheckConfidence("WilsonInterval", confidence);
  const double z = NormalQuantile(0.5 * (1.0 + confidence));
  const double nn = static_cast<double>(n), p = successes / nn, z2 = z * z;
  const double centre = (p + z2 / (2.0 * nn)) / (1.0 + z2 / nn);
  const double half = z / (1.0 + z2 / nn) * std::sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn));
  // At 0 or n successes the bound on that side is exactly 0 or 1; rounding would leave ~1e-17.
  return {successes == 0 ? 0.0 : centre - half, successes == n ? 1.0 : centre + half};
}

double KendallTauB(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size()) {
    Fail("KendallTauB", "scorings differ in length: " + std::to_string(a.size()) + " and " +
                            std::to_string(b.size()));
  }
  CheckFinite("KendallTauB", a);
  CheckFinite("KendallTauB", b);
  const auto sign = [](double d) { return (d > 0.0) - (d < 0.0); };
  long long concordance = 0, untied_a = 0, untied_b = 0;  // C - D, n0 - n1, n0 - n2
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = i + 1; j < a.size(); ++j) {
      const int sa = sign(a[i] - a[j]), sb = sign(b[i] - b[j]);
      concordance += sa * sb;
      untied_a += sa != 0;
      untied_b += sb != 0;
    }
  }
  if (untied_a == 0 || untied_b == 0) return 0.0;
  return static_cast<double>(concordance) /
         std::sqrt(static_cast<double>(untied_a) * static_cast<double>(untied_b));
}

}  // namespace foresight
