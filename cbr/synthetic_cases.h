// Large synthetic case bases for benchmarks and tests of the ball-scope index: the
// cases of a real case base (for one defending goal) copied `count` times, each copy mirrored in
// y with probability 1/2 (same defending goal), moved so that its ball lands uniformly on the
// field within `margin_m` of the lines, its teammates and opponents jittered by up to
// `jitter_m` in x and y, and its scopes (ball and opponents) multiplied by `scope_scale`.
// Deterministic in `seed` (common/random.h). Copies are named "<source>#<i>". Targets move with
// the ball like the teammates; kicks at goal stay kicks at goal.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cbr/case.h"
#include "cbr/symmetry.h"

namespace foresight {

struct SyntheticCaseSpec {
  int count = 10000;
  double half_length_m = 2.7;  // the Four-Legged field (models/fields/four_legged.json)
  double half_width_m = 1.8;
  double margin_m = 0.1;
  double jitter_m = 0.1;
  double scope_scale = 1.0;
  std::uint64_t seed = 13;
};

std::vector<Case> SyntheticCases(std::span<const Case> cases, const KickMirrors& mirrors,
                                 const SyntheticCaseSpec& spec);

}  // namespace foresight
