// Adapted positions and the correspondence problem (Ros et al. 2009, sec. 3.2, Fig. 5, 6).
//
//   adaptPos_i = tm_i^c - B^c + B^p          (the case's teammates move with the ball, Fig. 5)
//   cost(p, c) = sum_i dist(tm^p_{pi(i)}, adaptPos_i)      (sum, the paper's choice)
//              | max_i dist(...)                           (max, Fig. 6)
//              | (max_i dist, then sum_i dist)             (max_then_sum, lexicographic)
// minimised over the injective matchings pi: case teammates -> problem teammates, subject to
// dist <= thr_c for every matched robot (sec. 3.2: "the cost function includes one
// restriction"). At most 4 robots a side, so all n!/(n-m)! <= 24 matchings are enumerated
// (exact); ties go to the first matching in lexicographic order of problem-teammate indices.
// Nothing allocates: the arrays have room for kMaxTeammates robots.
#pragma once

#include <array>

#include "cbr/case.h"
#include "cbr/problem.h"
#include "cbr/retrieval_params.h"
#include "common/geometry.h"

namespace foresight {

inline constexpr int kMaxTeammates = 4;

// The cost of a matching, compared as (primary, secondary) lexicographically: sum: (sum, 0);
// max: (max, 0); max_then_sum: (max, sum).
struct CostKey {
  double primary = 0.0;
  double secondary = 0.0;
  bool operator<(const CostKey& o) const {
    return primary < o.primary || (primary == o.primary && secondary < o.secondary);
  }
};
CostKey MakeCostKey(CostFunction cost, double sum_m, double max_m);

struct Correspondence {
  int count = 0;  // matched robots == the case's teammates
  // For case teammate i (the case's order): the index of its problem teammate, its adapted
  // position and the distance the problem teammate has to walk there.
  std::array<int, kMaxTeammates> problem_index{};
  std::array<Vec2, kMaxTeammates> adapted_F{Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  std::array<double, kMaxTeammates> distance_m{};
  double sum_m = 0.0;
  double max_m = 0.0;
  CostKey cost;
  bool feasible = false;  // every distance <= thr_c
  // When infeasible: the matching with the smallest largest distance, and its farthest robot
  // (case teammate index, problem teammate index, distance): no matching does better.
  int far_case_index = -1;
  int far_problem_index = -1;
  double far_distance_m = 0.0;
};

// adaptPos of a case point (a teammate's position or a target): moved with the ball.
inline Vec2 AdaptedPosition(const Problem& problem, const Case& c, const Vec2& case_p_F) {
  return case_p_F - c.p_F_ball + problem.p_F_ball;
}

// A robot the matching must use: case teammate `case_index` is played by problem teammate
// `problem_index` (the CBR team's ball race, cbr/ball_race.h). None by default.
struct FixedPair {
  int case_index = -1;
  int problem_index = -1;
};

// The best feasible matching (among those with `fixed`, when given), or (feasible = false) the
// explanation why there is none.
// Precondition: 1 <= case teammates <= problem teammates <= kMaxTeammates.
Correspondence FindCorrespondence(const Problem& problem, const Case& c, CostFunction cost,
                                  double thr_cost_m, FixedPair fixed = {});

}  // namespace foresight
