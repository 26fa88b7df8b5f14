// Counter-based random streams and the project's own normal sampler.
//
// Determinism (docs/ARCHITECTURE.md): trial or sample i of a run draws only from its own stream,
// keyed by (seed, i), so results do not depend on the number of threads or the order of work. A
// stream is SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number generators",
// 2014): draw k is Mix64(key + k * golden_gamma). Normals come from the ziggurat method with 128
// layers (Marsaglia & Tsang 2000, in Doornik's ZIGNOR form, 2005), written here so every platform
// draws the same numbers (the standard library's distributions differ between implementations).
#pragma once

#include <cstdint>

namespace foresight {

inline constexpr std::uint64_t kGoldenGamma = 0x9E3779B97F4A7C15ULL;
// The odd constant that spreads a stream's domain over the keys.
inline constexpr std::uint64_t kDomainGamma = 0xD1B54A32D192ED03ULL;

// SplitMix64's output function. `Bits` is std::uint64_t or a vector of them (GCC/Clang vector
// extensions, planner/random_lanes.h): the same wrapping operations in every lane, one source.
template <typename Bits>
inline Bits Mix64Of(Bits z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}
inline std::uint64_t Mix64(std::uint64_t z) {
  return Mix64Of(z);
}

// StreamKey of each `index` (a std::uint64_t or a vector of them, as Mix64Of).
template <typename Bits>
inline Bits StreamKeyOf(std::uint64_t seed, Bits index, std::uint64_t domain) {
  return Mix64Of(Mix64(seed + kGoldenGamma) ^
                 Mix64Of(index * kGoldenGamma + domain * kDomainGamma));
}

// Key of stream `index` of a run seeded with `seed`; `domain` separates the uses of one seed
// (e.g. coarse samples and physics trials of the same run).
inline std::uint64_t StreamKey(std::uint64_t seed, std::uint64_t index, std::uint64_t domain = 0) {
  return StreamKeyOf(seed, index, domain);
}

namespace random_detail {
inline constexpr int kZigguratLayers = 128;
struct ZigguratTables {
  double x[kZigguratLayers + 1];  // layer edges, x[0] the base layer's virtual width
  double ratio[kZigguratLayers];  // x[i+1] / x[i]: the part of layer i surely under the curve
};
extern const ZigguratTables kZiggurat;
}  // namespace random_detail

class RandomStream {
 public:
  explicit RandomStream(std::uint64_t key) : state_(key) {}
  // The stream keyed `key` after its first `draws` NextBits (for code that made those draws
  // itself, e.g. in SIMD lanes).
  RandomStream(std::uint64_t key, std::uint64_t draws) : state_(key + draws * kGoldenGamma) {}

  std::uint64_t NextBits() {
    state_ += kGoldenGamma;
    return Mix64(state_);
  }
  // Uniform in [0, 1) with 53 random bits.
  double NextUniform() { return static_cast<double>(NextBits() >> 11) * 0x1.0p-53; }
  // Standard normal N(0, 1). The fast path (about 97 % of draws here) is inline.
  double NextNormal() {
    const std::uint64_t bits = NextBits();
    double x;
    return NormalInRectangle(bits, &x) ? x : NormalAfterMiss(bits);
  }

  // The ziggurat's fast path for one draw `bits`: true, with the normal in *x, when the point
  // falls inside its layer's rectangle (about 97 % of draws).
  static bool NormalInRectangle(std::uint64_t bits, double* x) {
    const int layer = static_cast<int>(bits & (random_detail::kZigguratLayers - 1));
    const double u = 2.0 * (static_cast<double>(bits >> 11) * 0x1.0p-53) - 1.0;  // [-1, 1)
    *x = u * random_detail::kZiggurat.x[layer];
    return u < random_detail::kZiggurat.ratio[layer] && u > -random_detail::kZiggurat.ratio[layer];
  }
  // NextNormal's slow path for a draw `bits` outside its layer's rectangle: the wedge or the
  // tail, drawing further numbers from this stream.
  double NormalAfterMiss(std::uint64_t bits) {
    const int layer = static_cast<int>(bits & (random_detail::kZigguratLayers - 1));
    return NormalEdge(layer, 2.0 * (static_cast<double>(bits >> 11) * 0x1.0p-53) - 1.0);
  }

 private:
  double NormalEdge(int layer, double u);  // the wedge and tail cases, then a fresh draw
  double NormalTail(bool negative);
  std::uint64_t state_;
};

// Counter-based normals: normal `index` (0, 1, ...) of the numbers keyed `key` is the ziggurat's
// fast path on draw index + 1 of RandomStream(key) (so a normal that lands in a rectangle, about
// 97 %, is NextNormal's when no earlier one missed), and a miss is finished with the draws of its
// own stream, EdgeStreamKey(key, index). Each normal then depends on its index alone, never on
// how many numbers an earlier one drew: SIMD lanes draw the fast paths of all normals side by
// side and finish the few misses together afterwards (planner/random_lanes.h). The
// distribution is the ziggurat's exactly: the fast path and the slow path's fresh draws are
// independent streams' numbers.
inline constexpr std::uint64_t kNormalEdgeDomain = 0x7a6967676564676bULL;
inline std::uint64_t EdgeStreamKey(std::uint64_t key, std::uint64_t index) {
  return StreamKey(key, index, kNormalEdgeDomain);
}
inline double IndexedNormal(std::uint64_t key, std::uint64_t index) {
  const std::uint64_t bits = Mix64(key + (index + 1) * kGoldenGamma);
  double x;
  if (RandomStream::NormalInRectangle(bits, &x)) return x;
  return RandomStream(EdgeStreamKey(key, index)).NormalAfterMiss(bits);
}

}  // namespace foresight
