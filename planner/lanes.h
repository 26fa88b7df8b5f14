// Two, four or eight samples at once: doubles in SIMD lanes through GCC/Clang vector extensions,
// so the hot path (planner/roll_lanes.h, PositionValue's lanes) reads like the scalar code it
// mirrors.
//
// A vector is as wide as the target's registers: 8 doubles where the build targets AVX-512F, 4
// with AVX, 2 on SSE only (the NAO's Atom E3845, -march=silvermont, and plain x86-64); vectors wider than the
// registers compile to slow code (measured: 4 lanes on SSE2 took 2.6 times the scalar code's
// time per hypothesis). The lane count never changes a result (below). Every operation is the IEEE
// operation of each lane (+, -, *, / and sqrt correctly rounded; no FMA, the build has
// -ffp-contract=off; no approximate reciprocals), so lane l gives exactly the bits of the scalar
// code run on sample l with the same operations in the same order, on every instruction set.
// The scalar code stays the reference (tests/planner/coarse_action_evaluator_test.cc compares
// the bits).
#pragma once

#include <cmath>
#include <cstdint>

#if defined(__AVX__)
#include <immintrin.h>
#endif

#include "common/fast_math.h"

namespace foresight {

#if defined(__AVX512F__)
inline constexpr int kLanes = 8;
#elif defined(__AVX__)
inline constexpr int kLanes = 4;
#else
inline constexpr int kLanes = 2;
#endif
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));
// Comparisons give -1 (all bits set) for true and 0 for false in each lane.
using LaneMask = std::int64_t __attribute__((vector_size(kLanes * sizeof(std::int64_t))));
using LaneBits = std::uint64_t __attribute__((vector_size(kLanes * sizeof(std::uint64_t))));

inline Lanes Broadcast(double x) {
  Lanes v{};
  for (int l = 0; l < kLanes; ++l) v[l] = x;  // exact, -0.0 included
  return v;
}
inline LaneMask BroadcastMask(std::int64_t x) {
  LaneMask v{};
  for (int l = 0; l < kLanes; ++l) v[l] = x;
  return v;
}

inline Lanes Select(LaneMask m, Lanes if_true, Lanes if_false) {
  return m ? if_true : if_false;
}
inline LaneMask Select(LaneMask m, LaneMask if_true, LaneMask if_false) {
  return m ? if_true : if_false;
}

// Whether some lane (Any) or every lane (All) of a mask is set: one test instruction where the
// target has one.
inline bool Any(LaneMask m) {
#if defined(__AVX512F__)
  return _mm512_test_epi64_mask(reinterpret_cast<__m512i>(m), reinterpret_cast<__m512i>(m)) != 0;
#elif defined(__AVX__)
  return !_mm256_testz_si256(reinterpret_cast<__m256i>(m), reinterpret_cast<__m256i>(m));
#else
  static_assert(kLanes == 2);
  return (m[0] | m[1]) != 0;
#endif
}
inline bool All(LaneMask m) {
  return !Any(~m);
}
// Bit l set where lane l of the mask is: one instruction where the target has one.
inline unsigned MaskBits(LaneMask m) {
#if defined(__AVX512F__)
  return _mm512_test_epi64_mask(reinterpret_cast<__m512i>(m), reinterpret_cast<__m512i>(m));
#elif defined(__AVX__)
  return static_cast<unsigned>(_mm256_movemask_pd(reinterpret_cast<__m256d>(m)));
#else
  unsigned bits = 0;
  for (int l = 0; l < kLanes; ++l) bits |= (m[l] != 0 ? 1U : 0U) << l;
  return bits;
#endif
}

// The mask whose lane l is set where bit l of `bits` is (MaskBits's inverse).
inline LaneMask MaskOfBits(unsigned bits) {
  LaneMask lane{};
  for (int l = 0; l < kLanes; ++l) lane[l] = l;
  return ((static_cast<std::int64_t>(bits) >> lane) & 1) != 0;
}

// std::min, std::max and std::clamp's definitions lane by lane (the same lane wins on ties).
inline Lanes Min(Lanes a, Lanes b) {
  return Select(b < a, b, a);
}
inline Lanes Max(Lanes a, Lanes b) {
  return Select(a < b, b, a);
}
inline Lanes Clamp(Lanes v, Lanes lo, Lanes hi) {
  return Select(v < lo, lo, Select(hi < v, hi, v));
}

inline Lanes Abs(Lanes x) {
  return reinterpret_cast<Lanes>(reinterpret_cast<LaneBits>(x) & 0x7fffffffffffffffULL);
}

// Correctly rounded in every lane (the compiler emits sqrtpd; planner/ builds with
// -fno-math-errno so that no lane needs a library call).
inline Lanes Sqrt(Lanes x) {
  Lanes r{};
  for (int l = 0; l < kLanes; ++l) r[l] = std::sqrt(x[l]);
  return r;
}

// table[index[l]] in each lane: one gather instruction with AVX2 or AVX-512, loads otherwise.
// A lookup, so every width reads the same bits.
inline Lanes Gather(const double* table, LaneBits index) {
#if defined(__AVX512F__)
  return reinterpret_cast<Lanes>(_mm512_mask_i64gather_pd(
      _mm512_setzero_pd(), 0xFF, reinterpret_cast<__m512i>(index), table, sizeof(double)));
#elif defined(__AVX2__)
  return reinterpret_cast<Lanes>(
      _mm256_i64gather_pd(table, reinterpret_cast<__m256i>(index), sizeof(double)));
#else
  Lanes v{};
  for (int l = 0; l < kLanes; ++l) v[l] = table[index[l]];
  return v;
#endif
}

inline Lanes Load(const double* p) {
  Lanes v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
inline LaneMask LoadMask(const std::int64_t* p) {
  LaneMask v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
inline void Store(Lanes v, double* p) {
  __builtin_memcpy(p, &v, sizeof v);
}
inline void StoreMask(LaneMask v, std::int64_t* p) {
  __builtin_memcpy(p, &v, sizeof v);
}

// RoundToInt (common/fast_math.h) in lanes: nearest integer, ties away from zero, by the same
// truncation: a rounding towards zero with AVX, a conversion to 32-bit integers and back with SSE
// (valid for |x| < 2^31; the callers' arguments stay below 10^5). The rounding gives -0.0
// where the conversion gives +0.0 (for x in (-0.5, 0)); every caller multiplies it by a constant
// and subtracts it from x, or takes its integer bits after adding 1.5 * 2^52, which gives the
// same bits either way.
inline Lanes RoundToIntLanes(Lanes x) {
  const Lanes shifted = x + Select(x >= 0.0, Broadcast(0.5), Broadcast(-0.5));
  // The conversion truncates; with AVX a rounding towards zero gives the same integral double in
  // one instruction (the conversion of 4 or 8 lanes to 32-bit integers and back takes five;
  // with 2 lanes it takes two, as fast as the rounding).
#if defined(__AVX512F__)
  // The zero-masked form: GCC's unmasked one warns of an undefined source operand.
  return reinterpret_cast<Lanes>(_mm512_maskz_roundscale_pd(
      0xFF, reinterpret_cast<__m512d>(shifted), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC));
#elif defined(__AVX__)
  return reinterpret_cast<Lanes>(
      _mm256_round_pd(reinterpret_cast<__m256d>(shifted), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC));
#else
  using LaneInts = std::int32_t __attribute__((vector_size(kLanes * sizeof(std::int32_t))));
  return __builtin_convertvector(__builtin_convertvector(shifted, LaneInts), Lanes);
#endif
}

// An integral n (|n| < 2^51) as a two's complement integer: n + 1.5 * 2^52 holds n exactly in
// its low mantissa bits (an integer conversion per lane is slow on SSE).
inline LaneBits IntegerBits(Lanes n) {
  constexpr double kShifter = 0x1.8p52;
  return reinterpret_cast<LaneBits>(n + kShifter) - reinterpret_cast<LaneBits>(Broadcast(kShifter));
}

// SinCos (common/fast_math.h) in lanes: the same reduction, polynomials and quadrant swap.
inline void SinCosLanes(Lanes x, Lanes* sin_x, Lanes* cos_x) {
  using namespace fast_math_detail;
  const Lanes k = RoundToIntLanes(x * kTwoOverPi);
  const Lanes r = (x - k * kPio2Hi) - k * kPio2Lo;
  const Lanes s = SinPoly(r), c = CosPoly(r);
  const LaneBits quadrant = IntegerBits(k) & 3;  // 0: (s, c), 1: (c, -s), 2: (-s, -c), 3: (-c, s)
  const LaneMask swap = (quadrant & 1) != 0;
  const Lanes sin_swapped = Select(swap, c, s), cos_swapped = Select(swap, s, c);
  *sin_x = Select((quadrant & 2) != 0, -sin_swapped, sin_swapped);
  *cos_x = Select(((quadrant + 1) & 2) != 0, -cos_swapped, cos_swapped);
}

// Exp (common/fast_math.h) in lanes, operation for operation: the same reduction to |r| <= ln2/2
// and series, no table. Lanes beyond +-700 take the scalar one.
inline Lanes ExpLanes(Lanes x) {
  using namespace fast_math_detail;
  if (Any((x < -700.0) | (x > 700.0))) {
    Lanes e{};
    for (int l = 0; l < kLanes; ++l) e[l] = Exp(x[l]);
    return e;
  }
  const Lanes k = RoundToIntLanes(x * kInvLn2);
  const Lanes r = (x - k * kLn2Hi) - k * kLn2Lo;
  return reinterpret_cast<Lanes>(reinterpret_cast<LaneBits>(ExpPoly(r)) + (IntegerBits(k) << 52));
}

// ExpFast (common/fast_math.h) in lanes, operation for operation: the same reduction
// x = (64 k + j) ln2 / 64 + r (n = 64 k + j rounded as RoundToInt), the same table 2^(j/64)
// and series. Lanes beyond +-700 (never met by the potential on a field) take the scalar one.
inline Lanes ExpFastLanes(Lanes x) {
  using fast_math_detail::kLn2Hi, fast_math_detail::kLn2Lo;
  constexpr double k64OverLn2 = 92.332482616893656877;
  if (Any((x < -700.0) | (x > 700.0))) {
    Lanes e{};
    for (int l = 0; l < kLanes; ++l) e[l] = ExpFast(x[l]);
    return e;
  }
  const Lanes n = RoundToIntLanes(x * k64OverLn2);
  const LaneBits ni = IntegerBits(n);
  const Lanes r = (x - n * (kLn2Hi / 64.0)) - n * (kLn2Lo / 64.0);
  const LaneBits j = ni & 63;
  const Lanes p =
      1.0 + r + r * r * (0.5 + r * (1.0 / 6 + r * (1.0 / 24 + r * (1.0 / 120 + r * (1.0 / 720)))));
  const Lanes table = Gather(fast_math_detail::GetExpTable().two_pow, j);
  // + k << 52 with k = (n - j) / 64, written as a left shift of the multiple of 64.
  const LaneBits bits = reinterpret_cast<LaneBits>(table * p) + ((ni - j) << 46);
  return reinterpret_cast<Lanes>(bits);
}

}  // namespace foresight
