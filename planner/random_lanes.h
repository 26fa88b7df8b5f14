// common/random.h's streams in SIMD lanes (planner/lanes.h): lane l holds its own stream, and a
// draw gives lane l exactly the bits RandomStream gives that stream. Only the ziggurat's fast path
// (a point inside a layer's rectangle, about 99 % of normals) is computed in lanes; a lane whose
// draw would take the slow path is reported, and its caller redraws that lane with the scalar
// stream (the slow path draws more numbers from the stream, which shifts every later draw).
#pragma once

#include <cstdint>

#include "common/random.h"
#include "planner/lanes.h"

namespace foresight {

inline LaneBits BroadcastBits(std::uint64_t x) {
  LaneBits v{};
  for (int l = 0; l < kLanes; ++l) v[l] = x;
  return v;
}

// Mix64 of each lane: the same integer operations (wrapping 64-bit products) per lane.
inline LaneBits Mix64Lanes(LaneBits z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// StreamKey(seed, first + l, domain) in lane l.
inline LaneBits StreamKeyLanes(std::uint64_t seed, std::uint64_t first, std::uint64_t domain = 0) {
  alignas(64) static constexpr std::uint64_t kLaneNumbers[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  LaneBits index;
  __builtin_memcpy(&index, kLaneNumbers, sizeof index);
  index += first;
  const std::uint64_t seed_mix = Mix64(seed + kGoldenGamma);
  return Mix64Lanes(BroadcastBits(seed_mix) ^
                    Mix64Lanes(index * kGoldenGamma +
                               static_cast<std::uint64_t>(domain * 0xD1B54A32D192ED03ULL)));
}

// Draw `draw` (1 for the first) of the streams keyed `key`: RandomStream(key)'s draw-th NextBits.
inline LaneBits StreamBitsLanes(LaneBits key, std::uint64_t draw) {
  return Mix64Lanes(key + draw * kGoldenGamma);
}

// RandomStream::NextNormal's fast path for `bits` in each lane; lanes whose point falls outside
// its layer's rectangle are cleared in `fast` (their value is then meaningless).
//
// The uniform u = 2 (b 2^-53) - 1 with b = bits >> 11 < 2^53 is exact (a multiple of 2^-52 in
// [-1, 1)); here it is built without an integer-to-double conversion (none is packed before
// AVX-512): m = 1 + (b mod 2^52) 2^-52 from the bits, then u = m - 1 when b's top bit is set
// and m - 2 otherwise, both exact. So u, the comparisons and u x[layer] have the scalar bits.
inline Lanes NormalFastLanes(LaneBits bits, LaneMask& fast) {
  const random_detail::ZigguratTables& t = random_detail::kZiggurat;
  const LaneBits layer = bits & static_cast<std::uint64_t>(random_detail::kZigguratLayers - 1);
  const LaneBits mantissa = (bits >> 11) & 0x000FFFFFFFFFFFFFULL;
  const Lanes m = reinterpret_cast<Lanes>(mantissa | 0x3FF0000000000000ULL);
  const LaneMask top = reinterpret_cast<LaneMask>(bits >> 63) != 0;
  const Lanes u = m - Select(top, Broadcast(1.0), Broadcast(2.0));
  const Lanes ratio = Gather(t.ratio, layer);
  fast &= (u < ratio) & (u > -ratio);
  return u * Gather(t.x, layer);
}

}  // namespace foresight
