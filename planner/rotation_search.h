// Choosing the rotation around the ball for one kick (step 1 of Mellmann & Schlotter, sec. IV).
//
// With common random numbers the trimmed utility u(rho) is a deterministic, piecewise smooth
// function of the rotation with jumps where a sample changes category. BestRotation finds its
// maximum over the whole circle reliably:
//   1. a grid over [-pi, pi) with step h (rotation_search.grid_step_deg, 20 deg in the shipped
//   files),
//      which includes rho = 0;
//   2. compass refinement (steps h/2, h/4, ... for refine_levels levels) from the best
//      `refine_candidates` local maxima of the grid;
//   3. among equal utilities the least |rho| wins, and the winner is walked and bisected
//      towards rho = 0 while its utility holds (the least turn that reaches the best value).
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

// Storage a search reuses between calls: once it holds a search's grid, later searches with the
// same parameters allocate nothing (a robot's decision cycle must not touch the heap).
struct RotationSearchScratch {
  std::vector<RotationChoice> grid;
  std::vector<int> maxima;
  std::vector<int> distinct;
  void Reserve(const RotationSearchParams& params);
};

RotationChoice BestRotation(const RotationObjective& evaluate, const RotationSearchParams& params,
                            RotationSearchScratch& scratch);
inline RotationChoice BestRotation(const RotationObjective& evaluate,
                                   const RotationSearchParams& params) {
  RotationSearchScratch scratch;
  return BestRotation(evaluate, params, scratch);
}

// Smallest |rho| with rho in direction `sign` (+1 counter-clockwise, -1 clockwise), up to pi,
// for which `acceptable` holds; nullopt if no rotation in that direction is acceptable.
std::optional<RotationChoice> LeastAcceptableRotation(
    const RotationObjective& evaluate,
    const std::function<bool(const ActionEvaluation&)>& acceptable, double sign,
    const RotationSearchParams& params);

// True when a is a better choice than b: higher trimmed utility, then the smaller turn.
bool BetterRotation(const RotationChoice& a, const RotationChoice& b);

}  // namespace foresight
