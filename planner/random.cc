#include "planner/random.h"

#include <array>
#include <cmath>

namespace foresight {

namespace {

constexpr int kLayers = 128;
// Start of the tail and area of each layer for 128 layers (Marsaglia & Tsang 2000).
constexpr double kTailStart = 3.442619855899;
constexpr double kLayerArea = 9.91256303526217e-3;

struct ZigguratTables {
  std::array<double, kLayers + 1> x{};  // layer edges, x[0] the base's virtual width
  std::array<double, kLayers> ratio{};  // x[i+1] / x[i]: the part of layer i under the curve

  ZigguratTables() {
    double f = std::exp(-0.5 * kTailStart * kTailStart);
    x[0] = kLayerArea / f;
    x[1] = kTailStart;
    for (int i = 2; i < kLayers; ++i) {
      x[i] = std::sqrt(-2.0 * std::log(kLayerArea / x[i - 1] + f));
      f = std::exp(-0.5 * x[i] * x[i]);
    }
    x[kLayers] = 0.0;
    for (int i = 0; i < kLayers; ++i) ratio[i] = x[i + 1] / x[i];
  }
};

const ZigguratTables& Tables() {
  static const ZigguratTables tables;
  return tables;
}

}  // namespace

double RandomStream::NormalTail(bool negative) {
  // Marsaglia (1964): exact sampling of the normal tail beyond kTailStart.
  double x, y;
  do {
    x = std::log(1.0 - NextUniform()) / kTailStart;
    y = std::log(1.0 - NextUniform());
  } while (-2.0 * y < x * x);
  return negative ? x - kTailStart : kTailStart - x;
}

double RandomStream::NextNormal() {
  const ZigguratTables& t = Tables();
  for (;;) {
    const std::uint64_t bits = NextBits();
    const int layer = static_cast<int>(bits & (kLayers - 1));
    const double u = 2.0 * (static_cast<double>(bits >> 11) * 0x1.0p-53) - 1.0;  // [-1, 1)
    if (std::abs(u) < t.ratio[layer]) return u * t.x[layer];  // inside the rectangle: ~99 %
    if (layer == 0) return NormalTail(u < 0.0);
    const double x = u * t.x[layer];
    const double f0 = std::exp(-0.5 * (t.x[layer] * t.x[layer] - x * x));
    const double f1 = std::exp(-0.5 * (t.x[layer + 1] * t.x[layer + 1] - x * x));
    if (f1 + NextUniform() * (f0 - f1) < 1.0) return x;
  }
}

}  // namespace foresight
