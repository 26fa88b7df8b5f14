#include "planner/rotation_search.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include "common/geometry.h"

namespace foresight {

namespace {

constexpr double kUtilityTolerance = 1e-12;

int GridSize(const RotationSearchParams& params) {
  // An even count so that the grid holds 0 and -pi.
  return 2 * static_cast<int>(std::ceil(kPi / params.grid_step_rad));
}

RotationChoice At(const RotationObjective& evaluate, double rotation_rad) {
  return {rotation_rad, evaluate(rotation_rad)};
}

// An exact strict weak order for sorting (BetterRotation's tolerance is not one): higher
// utility, then the smaller turn, then the counter-clockwise one.
bool SortsBefore(const RotationChoice& a, const RotationChoice& b) {
  const double ua = a.evaluation.trimmed_utility, ub = b.evaluation.trimmed_utility;
  if (ua != ub) return ua > ub;
  const double ta = std::abs(a.rotation_rad), tb = std::abs(b.rotation_rad);
  if (ta != tb) return ta < tb;
  return a.rotation_rad > b.rotation_rad;
}

// True when grid points j and k lie on one flat run: every point between them (the shorter
// way round) has the same utility.
bool SameFlatRun(const std::vector<RotationChoice>& grid, int j, int k) {
  const int n = static_cast<int>(grid.size());
  const int forward = (k - j + n) % n;
  const int step = forward <= n / 2 ? 1 : -1;
  const double u = grid[static_cast<std::size_t>(j)].evaluation.trimmed_utility;
  for (int i = j; i != k; i = (i + step + n) % n) {
    if (grid[static_cast<std::size_t>(i)].evaluation.trimmed_utility != u) return false;
  }
  return grid[static_cast<std::size_t>(k)].evaluation.trimmed_utility == u;
}

// Local maxima of the circular grid, best first, one per flat run (its least turn), into
// scratch.distinct.
void LocalMaxima(RotationSearchScratch& scratch) {
  const std::vector<RotationChoice>& grid = scratch.grid;
  const int n = static_cast<int>(grid.size());
  std::vector<int>& maxima = scratch.maxima;
  maxima.clear();
  for (int k = 0; k < n; ++k) {
    const double u = grid[k].evaluation.trimmed_utility;
    if (u >= grid[(k + n - 1) % n].evaluation.trimmed_utility &&
        u >= grid[(k + 1) % n].evaluation.trimmed_utility) {
      maxima.push_back(k);
    }
  }
  std::sort(maxima.begin(), maxima.end(),
            [&](int a, int b) { return SortsBefore(grid[a], grid[b]); });
  std::vector<int>& distinct = scratch.distinct;
  distinct.clear();
  for (int k : maxima) {
    bool seen = false;
    for (int j : distinct) seen = seen || SameFlatRun(grid, j, k);
    if (!seen) distinct.push_back(k);
  }
}

RotationChoice Refine(const RotationObjective& evaluate, RotationChoice best, double step,
                      int levels) {
  for (int level = 0; level < levels; ++level) {
    step *= 0.5;
    for (double direction : {-1.0, 1.0}) {
      RotationChoice trial = At(evaluate, WrapAngle(best.rotation_rad + direction * step));
      if (BetterRotation(trial, best)) best = trial;
    }
  }
  return best;
}

// Walks `best` towards rho = 0 while the utility holds, then bisects the step where it drops.
RotationChoice TowardsZero(const RotationObjective& evaluate, RotationChoice best, double step,
                           int levels) {
  const double target = best.evaluation.trimmed_utility - kUtilityTolerance;
  while (best.rotation_rad != 0.0) {
    const double toward = best.rotation_rad > 0.0 ? std::max(0.0, best.rotation_rad - step)
                                                  : std::min(0.0, best.rotation_rad + step);
    RotationChoice trial = At(evaluate, toward);
    if (trial.evaluation.trimmed_utility < target) {
      double fail = toward;
      for (int i = 0; i < levels + 2; ++i) {
        const double mid = 0.5 * (fail + best.rotation_rad);
        RotationChoice probe = At(evaluate, mid);
        if (probe.evaluation.trimmed_utility >= target)
          best = probe;
        else
          fail = mid;
      }
      return best;
    }
    best = trial;
  }
  return best;
}

}  // namespace

bool BetterRotation(const RotationChoice& a, const RotationChoice& b) {
  const double ua = a.evaluation.trimmed_utility, ub = b.evaluation.trimmed_utility;
  if (std::abs(ua - ub) > kUtilityTolerance) return ua > ub;
  return std::abs(a.rotation_rad) < std::abs(b.rotation_rad);
}

void RotationSearchScratch::Reserve(const RotationSearchParams& params) {
  const auto n = static_cast<std::size_t>(GridSize(params));
  grid.reserve(n);
  maxima.reserve(n);
  distinct.reserve(n);
}

RotationChoice BestRotation(const RotationObjective& evaluate, const RotationSearchParams& params,
                            RotationSearchScratch& scratch) {
  assert(params.grid_step_rad > 0.0 && params.refine_candidates >= 1);  // Validate() ensures it
  const int n = GridSize(params);
  const double step = 2.0 * kPi / n;
  std::vector<RotationChoice>& grid = scratch.grid;
  grid.clear();
  for (int k = -n / 2; k < n / 2; ++k) grid.push_back(At(evaluate, k * step));

  LocalMaxima(scratch);
  const std::vector<int>& maxima = scratch.distinct;
  RotationChoice best = grid[static_cast<std::size_t>(maxima.front())];
  const int candidates = std::min<int>(params.refine_candidates, static_cast<int>(maxima.size()));
  for (int c = 0; c < candidates; ++c) {
    RotationChoice refined =
        Refine(evaluate, grid[static_cast<std::size_t>(maxima[c])], step, params.refine_levels);
    if (BetterRotation(refined, best)) best = refined;
  }
  return TowardsZero(evaluate, best, step, params.refine_levels);
}

std::optional<RotationChoice> LeastAcceptableRotation(
    const RotationObjective& evaluate,
    const std::function<bool(const ActionEvaluation&)>& acceptable, double sign,
    const RotationSearchParams& params) {
  assert(params.grid_step_rad > 0.0);
  const int n = GridSize(params);
  const double step = 2.0 * kPi / n;
  RotationChoice at_zero = At(evaluate, 0.0);
  if (acceptable(at_zero.evaluation)) return at_zero;
  double fail = 0.0;
  for (int k = 1; k <= n / 2; ++k) {
    RotationChoice trial = At(evaluate, sign * k * step);
    if (!acceptable(trial.evaluation)) {
      fail = trial.rotation_rad;
      continue;
    }
    for (int i = 0; i < params.refine_levels + 2; ++i) {
      RotationChoice probe = At(evaluate, 0.5 * (fail + trial.rotation_rad));
      if (acceptable(probe.evaluation))
        trial = probe;
      else
        fail = probe.rotation_rad;
    }
    return trial;
  }
  return std::nullopt;
}

}  // namespace foresight
