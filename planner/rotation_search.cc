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

RotationChoice At(const SampledObjective& evaluate, double rotation_rad, int samples) {
  return {rotation_rad, evaluate(rotation_rad, samples)};
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

// The grid point k on all samples, evaluated once per search.
const RotationChoice& Full(const SampledObjective& evaluate, int k, int samples,
                           RotationSearchScratch& scratch) {
  const auto i = static_cast<std::size_t>(k);
  if (!scratch.has_full[i]) {
    scratch.full[i] = At(evaluate, scratch.grid[i].rotation_rad, samples);
    scratch.has_full[i] = 1;
  }
  return scratch.full[i];
}

// From grid point k, the grid's hill climbed on all samples: a look at few samples finds the
// hill but may misplace its top by a grid step or take a point beside a trimming cliff for it.
int Climb(const SampledObjective& evaluate, int k, int samples, RotationSearchScratch& scratch) {
  const int n = static_cast<int>(scratch.grid.size());
  for (int moves = 0; moves < n; ++moves) {
    const RotationChoice& here = Full(evaluate, k, samples, scratch);
    int next = k;
    for (int side : {-1, 1}) {
      const int j = (k + side + n) % n;
      if (BetterRotation(Full(evaluate, j, samples, scratch),
                         next == k ? here : Full(evaluate, next, samples, scratch))) {
        next = j;
      }
    }
    if (next == k) break;
    k = next;
  }
  return k;
}

// Compass refinement: steps step/2, step/4, ... for `levels` levels, the left neighbour first;
// when it wins, the right one is the old centre, already known to be worse, and is not probed.
struct Refined {
  RotationChoice best;
  // The neighbour one finest step towards rho = 0 was probed and is worse.
  bool worse_towards_zero = false;
};

Refined Refine(const SampledObjective& evaluate, RotationChoice best, double step, int levels,
               int samples) {
  Refined refined{best, false};
  for (int level = 0; level < levels; ++level) {
    step *= 0.5;
    const RotationChoice centre = refined.best;
    double moved = 0.0;  // the direction the centre moved in at this level, 0 if it stayed
    for (double direction : {-1.0, 1.0}) {
      RotationChoice trial =
          At(evaluate, WrapAngle(centre.rotation_rad + direction * step), samples);
      if (BetterRotation(trial, refined.best)) {
        refined.best = trial;
        moved = direction;
        break;
      }
    }
    // Known worse: both neighbours when the centre stayed, else the old centre behind it.
    const double rho = refined.best.rotation_rad;
    const double towards_zero = rho > 0.0 ? -1.0 : 1.0;
    refined.worse_towards_zero =
        std::abs(rho) >= step && (moved == 0.0 || moved == -towards_zero);
  }
  return refined;
}

// Walks `best` towards rho = 0 while the utility holds, then bisects the step where it drops.
// The utility of an optimum is rarely flat (every infield sample's value changes with the turn),
// so first one look `finest` towards 0 (usually the refinement's, else one probe): where the
// utility drops there, `best` stays.
RotationChoice TowardsZero(const SampledObjective& evaluate, const Refined& refined, double step,
                           double finest, int levels, int samples) {
  RotationChoice best = refined.best;
  if (best.rotation_rad == 0.0 || refined.worse_towards_zero) return best;
  const double target = best.evaluation.trimmed_utility - kUtilityTolerance;
  const auto toward_zero = [](double rho, double by) {
    return rho > 0.0 ? std::max(0.0, rho - by) : std::min(0.0, rho + by);
  };
  RotationChoice first = At(evaluate, toward_zero(best.rotation_rad, finest), samples);
  if (first.evaluation.trimmed_utility < target) return best;
  best = first;
  while (best.rotation_rad != 0.0) {
    const double toward = toward_zero(best.rotation_rad, step);
    RotationChoice trial = At(evaluate, toward, samples);
    if (trial.evaluation.trimmed_utility < target) {
      double fail = toward;
      for (int i = 0; i < levels + 2; ++i) {
        const double mid = 0.5 * (fail + best.rotation_rad);
        RotationChoice probe = At(evaluate, mid, samples);
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
  full.reserve(n);
  has_full.reserve(n);
  maxima.reserve(n);
  distinct.reserve(n);
}

RotationChoice BestRotation(const SampledObjective& evaluate, int samples,
                            const RotationSearchParams& params, RotationSearchScratch& scratch) {
  assert(params.grid_step_rad > 0.0 && params.refine_candidates >= 1);  // Validate() ensures it
  assert(samples >= 1);
  const int n = GridSize(params);
  const double step = 2.0 * kPi / n;
  const int coarse = params.CoarseSamples(samples);
  std::vector<RotationChoice>& grid = scratch.grid;
  grid.clear();
  for (int k = -n / 2; k < n / 2; ++k) grid.push_back(At(evaluate, k * step, coarse));

  LocalMaxima(scratch);
  const std::vector<int>& maxima = scratch.distinct;
  const int candidates = std::min<int>(params.refine_candidates, static_cast<int>(maxima.size()));
  if (coarse < samples) {
    scratch.full.assign(grid.size(), RotationChoice{});
    scratch.has_full.assign(grid.size(), 0);
  }
  // The grid on all samples: the points looked at with all of them.
  const auto on_all = [&](int k) -> const RotationChoice& {
    return coarse < samples ? scratch.full[static_cast<std::size_t>(k)]
                            : grid[static_cast<std::size_t>(k)];
  };
  int best = -1;
  for (int c = 0; c < candidates; ++c) {
    const int k = coarse < samples ? Climb(evaluate, maxima[c], samples, scratch) : maxima[c];
    if (best < 0 || BetterRotation(on_all(k), on_all(best))) best = k;
  }
  const Refined refined = Refine(evaluate, on_all(best), step, params.refine_levels, samples);
  return TowardsZero(evaluate, refined, step, std::ldexp(step, -params.refine_levels),
                     params.refine_levels, samples);
}

RotationChoice BestRotation(const RotationObjective& evaluate,
                            const RotationSearchParams& params) {
  RotationSearchScratch scratch;
  // One sample in all: the coarse stages' count is the full one.
  return BestRotation([&evaluate](double rho, int) { return evaluate(rho); }, 1, params, scratch);
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
