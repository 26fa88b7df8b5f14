// Goodness of fit: normality tests valid when the mean and sd are estimated from the same data
// (formulas and sources at the top of goodness_of_fit.cc). Conventions as in stats/statistics.h.
#pragma once

#include <span>

namespace foresight {

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
  // All values equal (a spread of 0, e.g. directions recorded as one number): no statistic
  // exists, the fields above are NaN and nothing is rejected.
  bool all_equal = false;
  bool Rejected(double level) const { return !all_equal && anderson_darling_p < level; }
};
NormalityTest TestNormality(std::span<const double> x);  // n >= 8, finite

}  // namespace foresight
