// Quantiles of a sorted sample with linear interpolation between order statistics: for q in
// [0, 1] and n values, position h = q (n - 1), Q(q) = x_(floor h) + (h - floor h)(x_(floor h + 1)
// - x_(floor h)) (Hyndman & Fan, "Sample quantiles in statistical packages", The American
// Statistician 50 (1996) 361-365, type 7; R's and NumPy's default). Equal neighbours, also
// infinite ones, are returned as they are.
#pragma once

#include <span>

namespace foresight {

// `sorted` ascending and not empty; q in [0, 1].
double QuantileOfSorted(std::span<const double> sorted, double q);

// One point of a quantile-quantile plot: a theoretical quantile and the observed one, same units.
struct QqPoint {
  double theoretical = 0.0;
  double observed = 0.0;
};

}  // namespace foresight
