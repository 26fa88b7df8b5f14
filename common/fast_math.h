// sin, cos, exp and log computed by the project itself, for determinism (and, for sin and cos,
// speed: SinCos is about 10 % faster than glibc's sin plus cos here; Exp is about 2x slower
// than glibc's, which costs a decision about 10 %). glibc picks
// different implementations (FMA or not) per CPU at run time, which may change the last bit of
// a result and with it the bytes of a report. These use only +, -, * and / in a fixed order
// (and -ffp-contract=off), so every x86-64 or ARM machine gives the same bits.
//
// Method (textbook): Cody-Waite range reduction to |r| <= pi/4 (sin, cos) or |r| <= ln2/2
// (exp), then truncated Taylor series whose remainder is below 1e-17 relative on that range:
// sin up to r^17, cos up to r^18, exp up to r^13. Accuracy: within 2 ulp of the correctly
// rounded value (tested against the standard library for |x| <= 1e3 rad and on [-700, 700]).
#pragma once

#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>

namespace foresight {

namespace fast_math_detail {

// pi/2 split so that k * kPio2Hi is exact for |k| < 2^20.
inline constexpr double kPio2Hi = 1.5707963267341256e+00;
inline constexpr double kPio2Lo = 6.0771005065061922e-11;
inline constexpr double kTwoOverPi = 0.63661977236758134308;

// Nearest integer (ties away from zero) with plain SSE2 conversions: std::nearbyint is a
// library call on x86-64 without SSE4.1. Valid for |x| < 2^52.
inline double RoundToInt(double x) {
  return static_cast<double>(static_cast<std::int64_t>(x + (x >= 0.0 ? 0.5 : -0.5)));
}

// Templates so that planner/lanes.h evaluates the same polynomials, operation for operation, on
// SIMD lanes (T = double or a vector of doubles).
template <typename T>
inline T SinPoly(T r) {
  const T r2 = r * r;
  // sum_{n=0..8} (-1)^n r^(2n+1) / (2n+1)!, Horner form.
  T p = T{} + 1.0 / 355687428096000.0;  // 1/17! (T{} + c: c as a T, whatever T is)
  p = p * r2 - 1.0 / 1307674368000.0;   // -1/15!
  p = p * r2 + 1.0 / 6227020800.0;      // 1/13!
  p = p * r2 - 1.0 / 39916800.0;        // -1/11!
  p = p * r2 + 1.0 / 362880.0;          // 1/9!
  p = p * r2 - 1.0 / 5040.0;            // -1/7!
  p = p * r2 + 1.0 / 120.0;             // 1/5!
  p = p * r2 - 1.0 / 6.0;               // -1/3!
  return r + r * r2 * p;
}

template <typename T>
inline T CosPoly(T r) {
  const T r2 = r * r;
  T p = T{} - 1.0 / 6402373705728000.0;  // -1/18!
  p = p * r2 + 1.0 / 20922789888000.0;   // 1/16!
  p = p * r2 - 1.0 / 87178291200.0;      // -1/14!
  p = p * r2 + 1.0 / 479001600.0;        // 1/12!
  p = p * r2 - 1.0 / 3628800.0;          // -1/10!
  p = p * r2 + 1.0 / 40320.0;            // 1/8!
  p = p * r2 - 1.0 / 720.0;              // -1/6!
  p = p * r2 + 1.0 / 24.0;               // 1/4!
  return 1.0 - 0.5 * r2 + r2 * r2 * p;
}

// exp(r) for |r| <= ln2 / 2 (Exp's series up to r^13), a template for the lanes as above.
template <typename T>
inline T ExpPoly(T r) {
  T p = T{} + 1.0 / 6227020800.0;  // 1/13!, then Horner down to 1/2!
  for (double c : {1.0 / 479001600, 1.0 / 39916800, 1.0 / 3628800, 1.0 / 362880, 1.0 / 40320,
                   1.0 / 5040, 1.0 / 720, 1.0 / 120, 1.0 / 24, 1.0 / 6, 0.5}) {
    p = p * r + c;
  }
  return 1.0 + r + r * r * p;
}

// exp's reduction constants: ln2 split so that k * kLn2Hi is exact for |k| < 2^20.
inline constexpr double kLn2Hi = 6.93147180369123816490e-01;
inline constexpr double kLn2Lo = 1.90821492927058770002e-10;
inline constexpr double kInvLn2 = 1.44269504088896338700e+00;

}  // namespace fast_math_detail

// sin(x) and cos(x) together.
// |x| < 1e5: angles enter through range-checked files, so larger ones are a programmer's bug.
inline void SinCos(double x, double* sin_x, double* cos_x) {
  using namespace fast_math_detail;
  assert(std::abs(x) < 1e5);
  const double k = RoundToInt(x * kTwoOverPi);
  const double r = (x - k * kPio2Hi) - k * kPio2Lo;
  const double s = SinPoly(r), c = CosPoly(r);
  switch (static_cast<std::int64_t>(k) & 3) {
    case 0:
      *sin_x = s;
      *cos_x = c;
      break;
    case 1:
      *sin_x = c;
      *cos_x = -s;
      break;
    case 2:
      *sin_x = -s;
      *cos_x = -c;
      break;
    default:
      *sin_x = -c;
      *cos_x = s;
      break;
  }
}

// exp(x); underflows to 0 below -708, overflows to +inf above 709.
inline double Exp(double x) {
  using fast_math_detail::kInvLn2, fast_math_detail::kLn2Hi, fast_math_detail::kLn2Lo;
  if (x < -708.0) return 0.0;
  if (x > 709.0) return INFINITY;
  const double k = fast_math_detail::RoundToInt(x * kInvLn2);
  const double r = (x - k * kLn2Hi) - k * kLn2Lo;  // |r| <= ln2 / 2
  const double e = fast_math_detail::ExpPoly(r);
  // Scale by 2^k through the exponent bits (k in [-1022, 1023] here, or nearly).
  const std::int64_t ki = static_cast<std::int64_t>(k);
  if (ki < -1021) return std::ldexp(e, static_cast<int>(ki));
  std::uint64_t bits;
  std::memcpy(&bits, &e, sizeof bits);
  bits += static_cast<std::uint64_t>(ki) << 52;
  double result;
  std::memcpy(&result, &bits, sizeof result);
  return result;
}

namespace fast_math_detail {
// 2^(j/64) for j = 0..63, computed once with Exp (so the same bits everywhere).
struct ExpTable {
  double two_pow[64];
  ExpTable() {
    for (int j = 0; j < 64; ++j) two_pow[j] = Exp(j * (6.93147180559945309417e-01 / 64.0));
  }
};
inline const ExpTable& GetExpTable() {
  static const ExpTable table;
  return table;
}
}  // namespace fast_math_detail

// exp(x) for the hot path, as fast as glibc's: x = (64 k + j) ln2 / 64 + r with |r| <= ln2/128,
// exp(x) = 2^k 2^(j/64) exp(r), exp(r) by its Taylor series up to r^6 (remainder < 2e-19).
// Within 3 ulp of the correctly rounded value (tested).
inline double ExpFast(double x) {
  using fast_math_detail::kLn2Hi, fast_math_detail::kLn2Lo;
  constexpr double k64OverLn2 = 92.332482616893656877;
  if (x < -700.0) return x < -745.0 ? 0.0 : Exp(x);
  if (x > 700.0) return Exp(x);
  const double n = fast_math_detail::RoundToInt(x * k64OverLn2);
  const double r = (x - n * (kLn2Hi / 64.0)) - n * (kLn2Lo / 64.0);
  const std::int64_t ni = static_cast<std::int64_t>(n);
  const std::int64_t j = ni & 63, k = (ni - j) / 64;
  const double p =
      1.0 + r + r * r * (0.5 + r * (1.0 / 6 + r * (1.0 / 24 + r * (1.0 / 120 + r * (1.0 / 720)))));
  double scaled = fast_math_detail::GetExpTable().two_pow[j] * p;
  std::uint64_t bits;
  std::memcpy(&bits, &scaled, sizeof bits);
  bits += static_cast<std::uint64_t>(k) << 52;
  std::memcpy(&scaled, &bits, sizeof scaled);
  return scaled;
}

// Natural logarithm for x > 0 (0: -inf, negative or NaN: NaN). x = 2^k m with m in
// [sqrt(1/2), sqrt(2)), log m = 2 atanh(s) = 2 (s + s^3/3 + s^5/5 + ...), s = (m-1)/(m+1),
// |s| <= 0.172; terms up to s^25 leave a remainder below 1e-20.
inline double Log(double x) {
  if (!(x > 0.0)) return x == 0.0 ? -INFINITY : NAN;
  if (x == INFINITY) return x;
  // x = m 2^k, m in [0.5, 1): std::frexp's result, from the bits for a normal x (frexp is a
  // library call; this runs in every normal's tail).
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int exponent = static_cast<int>(bits >> 52);  // x > 0: no sign bit
  int k = exponent - 1022;
  double m;
  if (exponent == 0) {
    m = std::frexp(x, &k);  // subnormal
  } else {
    bits = (bits & 0x000FFFFFFFFFFFFFULL) | 0x3FE0000000000000ULL;
    std::memcpy(&m, &bits, sizeof m);
  }
  if (m < 0.70710678118654752440) {
    m *= 2.0;
    --k;
  }
  const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
  double p = 1.0 / 25;
  for (double c : {1.0 / 23, 1.0 / 21, 1.0 / 19, 1.0 / 17, 1.0 / 15, 1.0 / 13, 1.0 / 11, 1.0 / 9,
                   1.0 / 7, 1.0 / 5, 1.0 / 3}) {
    p = p * s2 + c;
  }
  using fast_math_detail::kLn2Hi, fast_math_detail::kLn2Lo;
  return k * kLn2Hi + (2.0 * s + 2.0 * s * s2 * p + k * kLn2Lo);
}

}  // namespace foresight
