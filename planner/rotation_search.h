// Choosing the rotation around the ball for one kick (step 1 of Mellmann & Schlotter, sec. IV).
//
// With common random numbers the trimmed utility u(rho) is a deterministic, piecewise smooth
// function of the rotation with jumps where a sample changes category. BestRotation finds its
// maximum over the whole circle reliably:
//   1. a grid over [-pi, pi) with step h (rotation_search.grid_step_deg, 20 deg in the shipped
//      files), which includes rho = 0;
//   2. the best `refine_candidates` local maxima of the grid are compared on all N samples, and
//      the best of them is refined by compass search (steps h/2, h/4, ... for refine_levels
//      levels);
//   3. among equal utilities the least |rho| wins, and the winner is walked and bisected
//      towards rho = 0 while its utility holds (the least turn that reaches the best value);
//      a neighbour a finest step towards 0 that is worse (the refinement's last level has
//      usually seen it) ends the walk at once: most optima are peaks, not plateaus.
// Coarse then fine: the grid only finds the hills, so it looks at the first
// ceil(coarse_sample_share * N) samples (u(rho) from fewer of the same common random numbers),
// trimmed only where all N samples certainly are (HypothesisAccumulator::Finish with N), so that
// no hill the N samples keep is lost to a look at few. Candidates are compared, refined and
// walked on all N: the chosen rotation's utility is the paper's N-sample one (eqs. 5, 6), and
// every comparison is between evaluations of the same samples.
// LeastAcceptableRotation finds the smallest turn in one direction that makes a kick
// acceptable: a grid scan, then bisection of the first grid step that succeeds.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "models/evaluation_params.h"
#include "planner/hypothesis.h"

namespace foresight {

struct RotationChoice {
  double rotation_rad = 0.0;
  ActionEvaluation evaluation;
};

// The evaluation of one kick at a rotation.
using RotationObjective = std::function<ActionEvaluation(double rotation_rad)>;
// The same from the first `samples` of the evaluator's samples (1..N).
using SampledObjective = std::function<ActionEvaluation(double rotation_rad, int samples)>;

// Storage a search reuses between calls: once it holds a search's grid, later searches with the
// same parameters allocate nothing (a robot's decision cycle must not touch the heap).
struct RotationSearchScratch {
  std::vector<RotationChoice> grid;
  std::vector<RotationChoice> full;  // grid points on all samples, when the grid looked at fewer
  std::vector<char> has_full;
  std::vector<int> maxima;
  std::vector<int> distinct;
  void Reserve(const RotationSearchParams& params);
};

// The best rotation of an objective over N = `samples` samples.
RotationChoice BestRotation(const SampledObjective& evaluate, int samples,
                            const RotationSearchParams& params, RotationSearchScratch& scratch);
inline RotationChoice BestRotation(const SampledObjective& evaluate, int samples,
                                   const RotationSearchParams& params) {
  RotationSearchScratch scratch;
  return BestRotation(evaluate, samples, params, scratch);
}
// An objective without samples to leave out (synthetic ones): every stage sees all of it.
RotationChoice BestRotation(const RotationObjective& evaluate, const RotationSearchParams& params);

// Smallest |rho| with rho in direction `sign` (+1 counter-clockwise, -1 clockwise), up to pi,
// for which `acceptable` holds; nullopt if no rotation in that direction is acceptable.
std::optional<RotationChoice> LeastAcceptableRotation(
    const RotationObjective& evaluate,
    const std::function<bool(const ActionEvaluation&)>& acceptable, double sign,
    const RotationSearchParams& params);

// True when a is a better choice than b: higher trimmed utility, then the smaller turn.
bool BetterRotation(const RotationChoice& a, const RotationChoice& b);

}  // namespace foresight
