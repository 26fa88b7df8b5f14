// Bitwise equality, for the promise "same seed, same bytes": two doubles are the same when their
// bits are (so -0.0 differs from 0.0 and a NaN equals itself), and a struct compared field by
// field can count its fields at compile time, so a field added later cannot be left out of the
// comparison silently (see SameBits(const Outcome&, const Outcome&), models/outcome.h).
#pragma once

#include <cstddef>
#include <cstring>

namespace foresight {

inline bool SameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

namespace same_bits_detail {
struct AnyField {
  template <typename T>
  operator T() const;  // never defined: only used in unevaluated brace-initialisation
};
}  // namespace same_bits_detail

// The number of fields of an aggregate without bases or arrays: the largest N for which
// T{x1, ..., xN} compiles with arguments that convert to anything.
template <typename T, typename... Fields>
constexpr std::size_t AggregateFieldCount() {
  using Any = same_bits_detail::AnyField;
  if constexpr (requires { T{Fields{}..., Any{}}; }) {
    return AggregateFieldCount<T, Fields..., Any>();
  } else {
    return sizeof...(Fields);
  }
}

}  // namespace foresight
