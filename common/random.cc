#include "common/random.h"

#include <array>
#include <cmath>

#include "common/fast_math.h"

namespace foresight {

namespace {

// Start of the tail and area of each layer for 128 layers (Marsaglia & Tsang 2000).
constexpr double kTailStart = 3.442619855899;
constexpr double kLayerArea = 9.91256303526217e-3;
constexpr int kLayers = random_detail::kZigguratLayers;

random_detail::ZigguratTables MakeTables() {
  random_detail::ZigguratTables t{};
  double f = Exp(-0.5 * kTailStart * kTailStart);
  t.x[0] = kLayerArea / f;
  t.x[1] = kTailStart;
  for (int i = 2; i < kLayers; ++i) {
    t.x[i] = std::sqrt(-2.0 * Log(kLayerArea / t.x[i - 1] + f));
    f = Exp(-0.5 * t.x[i] * t.x[i]);
  }
  t.x[kLayers] = 0.0;
  for (int i = 0; i < kLayers; ++i) t.ratio[i] = t.x[i + 1] / t.x[i];
  return t;
}

}  // namespace

// Built before main(); no static initialiser of the project draws random numbers.
const random_detail::ZigguratTables random_detail::kZiggurat = MakeTables();

double RandomStream::NormalTail(bool negative) {
  // Marsaglia (1964): exact sampling of the normal tail beyond kTailStart.
  double x, y;
  do {
    x = Log(1.0 - NextUniform()) / kTailStart;
    y = Log(1.0 - NextUniform());
  } while (-2.0 * y < x * x);
  return negative ? x - kTailStart : kTailStart - x;
}

double RandomStream::NormalEdge(int layer, double u) {
  const random_detail::ZigguratTables& t = random_detail::kZiggurat;
  for (;;) {
    if (layer == 0) return NormalTail(u < 0.0);
    const double x = u * t.x[layer];
    const double f0 = Exp(-0.5 * (t.x[layer] * t.x[layer] - x * x));
    const double f1 = Exp(-0.5 * (t.x[layer + 1] * t.x[layer + 1] - x * x));
    if (f1 + NextUniform() * (f0 - f1) < 1.0) return x;
    // Rejected: a fresh draw, which usually lands in a rectangle.
    const std::uint64_t bits = NextBits();
    layer = static_cast<int>(bits & (kLayers - 1));
    u = 2.0 * (static_cast<double>(bits >> 11) * 0x1.0p-53) - 1.0;
    if (std::abs(u) < t.ratio[layer]) return u * t.x[layer];
  }
}

}  // namespace foresight
