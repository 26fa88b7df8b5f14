// common/random.h's streams in SIMD lanes (planner/lanes.h): lane l holds its own stream, and a
// draw gives lane l exactly the bits RandomStream gives that stream. The ziggurat's fast path (a
// point inside a layer's rectangle, about 97 % of normals) and its wedge (the slow path's usual
// case, which draws more numbers from the stream) are computed in lanes; only a lane that reaches
// the tail is reported, for its caller to draw with the scalar stream.
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

// Mix64 of each lane (common/random.h's Mix64Of: the same wrapping products per lane).
inline LaneBits Mix64Lanes(LaneBits z) {
  return Mix64Of(z);
}

// StreamKey(seed, first + l, domain) in lane l.
inline LaneBits StreamKeyLanes(std::uint64_t seed, std::uint64_t first, std::uint64_t domain = 0) {
  alignas(64) static constexpr std::uint64_t kLaneNumbers[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  LaneBits index;
  __builtin_memcpy(&index, kLaneNumbers, sizeof index);
  return StreamKeyOf(seed, index + first, domain);
}

// Draw `draw` (1 for the first) of the streams keyed `key`: RandomStream(key)'s draw-th NextBits.
inline LaneBits StreamBitsLanes(LaneBits key, std::uint64_t draw) {
  return Mix64Lanes(key + draw * kGoldenGamma);
}

// RandomStream::NextBits in the lanes of `active`: `state` is each lane's RandomStream state (its
// key plus its draws times the golden gamma); inactive lanes keep theirs.
inline LaneBits NextBitsLanes(LaneBits& state, LaneMask active) {
  state += reinterpret_cast<LaneBits>(active) & kGoldenGamma;
  return Mix64Lanes(state);
}

// RandomStream::NextUniform of `bits` in each lane: b 2^-53 with b = bits >> 11 < 2^53, exact.
inline Lanes UniformLanes(LaneBits bits) {
  return __builtin_convertvector(bits >> 11, Lanes) * 0x1.0p-53;
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

// RandomStream::NormalEdge in the lanes of `pending`, whose draw `bits` fell outside its layer's
// rectangle: the wedge test (Exp's bits, ExpLanes), the uniform it draws and the fresh draws
// after a rejection, each lane from its own stream as the scalar code draws, so `state` ends
// where the scalar stream's would. The tail (layer 0, about 6 in 10,000 normals) needs logs and
// a loop: a lane that reaches it is set in `tail`, its value and state left meaningless, for the
// caller to draw that normal with the scalar stream. Out of line: about 2.8 % of normals come
// here.
[[gnu::noinline]] inline void NormalEdgeLanes(LaneBits bits, LaneMask pending, LaneBits& state,
                                              Lanes& value, LaneMask& tail) {
  const random_detail::ZigguratTables& t = random_detail::kZiggurat;
  for (;;) {
    const LaneBits layer = bits & static_cast<std::uint64_t>(random_detail::kZigguratLayers - 1);
    const LaneMask at_tail = pending & (reinterpret_cast<LaneMask>(layer) == 0);
    tail |= at_tail;
    pending &= ~at_tail;
    if (!Any(pending)) return;
    // NormalFastLanes's u and x = u x[layer], then the wedge test in the lanes still pending.
    LaneMask unused = pending;
    const Lanes x = NormalFastLanes(bits, unused);
    const Lanes x_layer = Gather(t.x, layer), x_next = Gather(t.x, layer + 1);
    const Lanes f0 = ExpLanes(-0.5 * (x_layer * x_layer - x * x));
    const Lanes f1 = ExpLanes(-0.5 * (x_next * x_next - x * x));
    const Lanes uniform = UniformLanes(NextBitsLanes(state, pending));
    const LaneMask accept = pending & (f1 + uniform * (f0 - f1) < 1.0);
    value = Select(accept, x, value);
    pending &= ~accept;
    if (!Any(pending)) return;
    // Rejected: a fresh draw, accepted when it lands in its layer's rectangle.
    bits = NextBitsLanes(state, pending);
    LaneMask fast = pending;
    const Lanes fresh = NormalFastLanes(bits, fast);
    value = Select(fast, fresh, value);
    pending &= ~fast;
    if (!Any(pending)) return;
  }
}

// IndexedNormal's fast path (common/random.h) for normal `index` of the keys `key`, one key per
// lane: the draw in *bits, and lanes whose point falls outside its layer's rectangle cleared in
// `fast` (FinishMissedNormals finishes them).
inline Lanes IndexedNormalFastLanes(LaneBits key, std::uint64_t index, LaneBits* bits,
                                    LaneMask& fast) {
  *bits = StreamBitsLanes(key, index + 1);
  return NormalFastLanes(*bits, fast);
}

// A normal whose fast path missed: IndexedNormal(key, index), whose draw was `bits`, goes to
// *value.
struct MissedNormal {
  double* value;
  std::uint64_t key, index, bits;
};

// IndexedNormal for each of `count` missed normals, kLanes at a time: the wedges in lanes
// (NormalEdgeLanes, each lane from its normal's own stream EdgeStreamKey(key, index)); a lane
// that reaches the tail is drawn again by the scalar IndexedNormal. The missed normals of many
// samples share one pass, so the wedge's latency is paid about once per decision, not once per
// lane group that has a miss.
[[gnu::noinline]] inline void FinishMissedNormals(const MissedNormal* missed, int count) {
  for (int first = 0; first < count; first += kLanes) {
    LaneBits bits = BroadcastBits(0), state = BroadcastBits(0);
    LaneMask pending = BroadcastMask(0);
    for (int l = 0; l < kLanes && first + l < count; ++l) {
      const MissedNormal& m = missed[first + l];
      bits[l] = m.bits;
      state[l] = EdgeStreamKey(m.key, m.index);
      pending[l] = -1;
    }
    Lanes value = Broadcast(0.0);
    LaneMask tail = BroadcastMask(0);
    NormalEdgeLanes(bits, pending, state, value, tail);
    for (int l = 0; l < kLanes && first + l < count; ++l) {
      const MissedNormal& m = missed[first + l];
      *m.value = tail[l] ? IndexedNormal(m.key, m.index) : value[l];
    }
  }
}

}  // namespace foresight
