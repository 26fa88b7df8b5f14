#include "cbr/correspondence.h"

#include <algorithm>
#include <cassert>
#include <limits>

namespace foresight {
namespace {

struct Search {
  int m = 0;                                 // case teammates
  int n = 0;                                 // problem teammates
  double d[kMaxTeammates][kMaxTeammates]{};  // d[case][problem]
  CostFunction cost = CostFunction::kSum;
  double thr = 0.0;
  FixedPair fixed;
  std::array<int, kMaxTeammates> current{};
  bool used[kMaxTeammates]{};
  // The best feasible matching.
  bool found = false;
  CostKey best_key;
  double best_sum = 0.0, best_max = 0.0;
  std::array<int, kMaxTeammates> best{};
  // The matching with the smallest largest distance (for the explanation).
  double minmax = std::numeric_limits<double>::infinity();
  std::array<int, kMaxTeammates> minmax_match{};

  void Visit(int i, double sum, double max) {
    if (i == m) {
      if (max < minmax) {
        minmax = max;
        minmax_match = current;
      }
      if (max > thr) return;
      const CostKey key = MakeCostKey(cost, sum, max);
      if (!found || key < best_key) {
        found = true;
        best_key = key;
        best_sum = sum;
        best_max = max;
        best = current;
      }
      return;
    }
    if (i >= kMaxTeammates) return;  // unreachable (m <= kMaxTeammates); tells the compiler
    for (int j = 0; j < n; ++j) {
      if (used[j] || (i == fixed.case_index && j != fixed.problem_index)) continue;
      used[j] = true;
      current[i] = j;
      Visit(i + 1, sum + d[i][j], std::max(max, d[i][j]));
      used[j] = false;
    }
  }
};

}  // namespace

CostKey MakeCostKey(CostFunction cost, double sum_m, double max_m) {
  switch (cost) {
    case CostFunction::kSum:
      return {sum_m, 0.0};
    case CostFunction::kMax:
      return {max_m, 0.0};
    case CostFunction::kMaxThenSum:
      return {max_m, sum_m};
  }
  return {sum_m, 0.0};
}

Correspondence FindCorrespondence(const Problem& problem, const Case& c, CostFunction cost,
                                  double thr_cost_m, FixedPair fixed) {
  Search s;
  s.fixed = fixed;
  s.m = static_cast<int>(c.teammates.size());
  s.n = static_cast<int>(problem.teammates.size());
  assert(s.m >= 1 && s.m <= s.n && s.n <= kMaxTeammates);
  s.cost = cost;
  s.thr = thr_cost_m;
  Correspondence out;
  out.count = s.m;
  for (int i = 0; i < s.m; ++i) {
    out.adapted_F[i] = AdaptedPosition(problem, c, c.teammates[i].p_F);
    for (int j = 0; j < s.n; ++j) {
      s.d[i][j] = (problem.teammates[j].pose.p_F - out.adapted_F[i]).norm();
    }
  }
  s.Visit(0, 0.0, 0.0);
  out.feasible = s.found;
  const std::array<int, kMaxTeammates>& match = s.found ? s.best : s.minmax_match;
  for (int i = 0; i < s.m; ++i) {
    out.problem_index[i] = match[i];
    out.distance_m[i] = s.d[i][match[i]];
    out.sum_m += out.distance_m[i];
    out.max_m = std::max(out.max_m, out.distance_m[i]);
  }
  out.cost = MakeCostKey(cost, out.sum_m, out.max_m);
  if (!s.found) {
    for (int i = 0; i < s.m; ++i) {
      if (out.distance_m[i] == out.max_m) {
        out.far_case_index = i;
        out.far_problem_index = match[i];
        out.far_distance_m = out.max_m;
        break;
      }
    }
  }
  return out;
}

}  // namespace foresight
