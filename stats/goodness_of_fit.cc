// Normality tests of stats/goodness_of_fit.h with mean and sd estimated from the same data.
//
// Formulas and sources (w_i = (x_(i) - mean) / s sorted, s with divisor n - 1, z_i = Phi(w_i)):
//   Anderson-Darling   A^2 = -n - (1/n) sum_i (2i - 1) [ln z_i + ln(1 - z_{n+1-i})]
//                      (Anderson & Darling, JASA 49 (1954)); case 3 (both parameters estimated)
//                      modification A*^2 = A^2 (1 + 0.75/n + 2.25/n^2) and its p-value
//                      (D'Agostino & Stephens, Goodness-of-Fit Techniques, 1986, table 4.9):
//                        A*^2 <  0.2    p = 1 - exp(-13.436 + 101.14 A*^2 - 223.73 A*^4)
//                        A*^2 <  0.34   p = 1 - exp(-8.318 + 42.796 A*^2 - 59.938 A*^4)
//                        A*^2 <  0.6    p = exp(0.9177 - 4.279 A*^2 - 1.38 A*^4)
//                        otherwise      p = exp(1.2937 - 5.709 A*^2 + 0.0186 A*^4)
//                      The last quadratic turns upwards at A*^2 = 5.709 / 0.0372 = 153.5, far
//                      outside its table (p there is about 1e-190), so p = 0 beyond that.
//   Lilliefors         D = max_i max(i/n - z_i, z_i - (i-1)/n) (Lilliefors, JASA 62 (1967)),
//                      p from Dallal & Wilkinson, The American Statistician 40 (1986) 294-296:
//                        p = exp(-7.01256 D^2 (n + 2.78019) + 2.99587 D sqrt(n + 2.78019)
//                                - 0.122119 + 0.974598 / sqrt(n) + 1.67997 / n),
//                      for n > 100 with D replaced by D (n/100)^0.49 and n by 100.
//                      Dallal & Wilkinson vouch for it only for p <= 0.1. Above 0.1 we keep the
//                      same formula, clamped to 1, rather than the Kolmogorov asymptotic of
//                      Stephens' modified statistic D (sqrt(n) - 0.01 + 0.85/sqrt(n)): that
//                      asymptotic is for a fully specified distribution and gives p = 0.50 where
//                      the true Lilliefors p is 0.10. A one-off simulation (2e5 normal samples
//                      each for n = 8, 20, 50, 200; 4e4 for n = 1000) found the formula within
//                      0.01 of the true p up to 0.1, within 0.04 up to 0.3 and within 0.1 up to
//                      0.5; above that it is indicative only (for n = 8 it passes 1 before the
//                      true p reaches 0.9).
#include "stats/goodness_of_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "stats/distributions.h"

namespace foresight {
namespace {

// ln Phi(w), finite even where Phi(w) underflows: the asymptotic Mills-ratio series
// ln Phi(w) = -w^2/2 - ln(-w) - ln(2 pi)/2 + ln(1 - 1/w^2 + 3/w^4 - ...) (A&S 26.2.12) below -35.
double LogNormalCdf(double w) {
  if (w > -35.0) return std::log(NormalCdf(w));
  const double inv2 = 1.0 / (w * w);
  return -0.5 * w * w - std::log(-w) - 0.5 * std::log(2.0 * std::numbers::pi) +
         std::log1p(-inv2 + 3.0 * inv2 * inv2);
}

// Case-3 p-value of the modified statistic A*^2 (D'Agostino & Stephens 1986, table 4.9).
double AndersonDarlingP(double a) {
  double p;
  if (a < 0.2) {
    p = 1.0 - std::exp(-13.436 + 101.14 * a - 223.73 * a * a);
  } else if (a < 0.34) {
    p = 1.0 - std::exp(-8.318 + 42.796 * a - 59.938 * a * a);
  } else if (a < 0.6) {
    p = std::exp(0.9177 - 4.279 * a - 1.38 * a * a);
  } else if (a < 153.0) {
    p = std::exp(1.2937 - 5.709 * a + 0.0186 * a * a);
  } else {
    p = 0.0;
  }
  return std::clamp(p, 0.0, 1.0);
}

// Dallal & Wilkinson (1986) p-value of the Lilliefors statistic, clamped to [0, 1].
double LillieforsP(double d, int n) {
  double dd = d, nn = static_cast<double>(n);
  if (n > 100) {
    dd = d * std::pow(nn / 100.0, 0.49);
    nn = 100.0;
  }
  const double p =
      std::exp(-7.01256 * dd * dd * (nn + 2.78019) + 2.99587 * dd * std::sqrt(nn + 2.78019) -
               0.122119 + 0.974598 / std::sqrt(nn) + 1.67997 / nn);
  return std::clamp(p, 0.0, 1.0);
}

// The sample, sorted and standardized with its own mean and sd (divisor n - 1).
std::vector<double> Standardized(std::span<const double> x) {
  std::vector<double> w(x.begin(), x.end());
  std::sort(w.begin(), w.end());
  const double n = static_cast<double>(w.size());
  double mean = 0.0;
  for (double v : w) mean += v;
  mean /= n;
  double ss = 0.0;
  for (double v : w) ss += (v - mean) * (v - mean);
  const double sd = std::sqrt(ss / (n - 1.0));
  if (!(sd > 0.0)) throw std::invalid_argument("TestNormality: all values are equal");
  for (double& v : w) v = (v - mean) / sd;
  return w;
}

double AndersonDarlingA2(const std::vector<double>& w) {
  const std::size_t n = w.size();
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    // ln(1 - Phi(w)) = ln Phi(-w), accurate in the upper tail too.
    sum +=
        (2.0 * static_cast<double>(i) + 1.0) * (LogNormalCdf(w[i]) + LogNormalCdf(-w[n - 1 - i]));
  }
  return -static_cast<double>(n) - sum / static_cast<double>(n);
}

double LillieforsD(const std::vector<double>& w) {
  const double n = static_cast<double>(w.size());
  double d = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double z = NormalCdf(w[i]);
    d = std::max({d, (static_cast<double>(i) + 1.0) / n - z, z - static_cast<double>(i) / n});
  }
  return d;
}

}  // namespace

NormalityTest TestNormality(std::span<const double> x) {
  if (x.size() < 8) {
    throw std::invalid_argument("TestNormality: need at least 8 values, got " +
                                std::to_string(x.size()));
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw std::invalid_argument("TestNormality: non-finite value at index " + std::to_string(i));
    }
  }
  NormalityTest test;
  test.n = static_cast<int>(x.size());
  if (std::all_of(x.begin(), x.end(), [&](double v) { return v == x[0]; })) {
    test.all_equal = true;
    test.anderson_darling = test.anderson_darling_p = std::numeric_limits<double>::quiet_NaN();
    test.lilliefors_d = test.lilliefors_p = std::numeric_limits<double>::quiet_NaN();
    return test;
  }
  const std::vector<double> w = Standardized(x);
  const double n = static_cast<double>(test.n);
  test.anderson_darling = AndersonDarlingA2(w) * (1.0 + 0.75 / n + 2.25 / (n * n));
  test.anderson_darling_p = AndersonDarlingP(test.anderson_darling);
  test.lilliefors_d = LillieforsD(w);
  test.lilliefors_p = LillieforsP(test.lilliefors_d, test.n);
  return test;
}

}  // namespace foresight
