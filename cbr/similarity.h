// Ball similarity and opponent similarity (Ros et al. 2009, sec. 3.1 and 3.3.2).
//
//   G(dx, dy; tau) = exp(-[(dx / tau_x)^2 + (dy / tau_y)^2])       (sec. 3.1; = exp(-1) on the
//                                                                   scope ellipse, Fig. 4)
//   sim_B(p, c)    = G(B^p - B^c; ball scope of c)                 (sec. 3.1)
//   Omega_j(o)     = G(o - s_j; tau_j),  s_j = opp_j^c - B^c + B^p  (sec. 3.3.2; the scope moves
//                                                                   with the ball, Fig. 2b)
//   sim_opp(p, c)  = |{ j : exists problem opponent o with Omega_j(o) > thr_opp }|  ("conditions")
#pragma once

#include <cmath>

#include "cbr/case.h"
#include "cbr/problem.h"
#include "common/geometry.h"

namespace foresight {

// G of sec. 3.1: 1 at the centre, exp(-1) on the ellipse with radii tau.
inline double ScopeGaussian(const Vec2& d, const Scope& tau) {
  const double u = d.x() / tau.tau_x_m;
  const double v = d.y() / tau.tau_y_m;
  return std::exp(-(u * u + v * v));
}

// sim_B: the problem ball within the case's ball scope.
double BallSimilarity(const Problem& problem, const Case& c);

// The centre of case opponent `opponent`'s scope moved with the ball: opp^c - B^c + B^p.
Vec2 MovedScopeCentre(const Problem& problem, const Case& c, const CaseOpponent& opponent);

// Omega of case opponent `opponent`'s scope at problem position p_F.
double OpponentScopeMembership(const Problem& problem, const Case& c, const CaseOpponent& opponent,
                               const Vec2& p_F);

// sim_opp: the number of case opponent scopes occupied by at least one problem opponent
// (Omega > thr_opp).
int OpponentSimilarity(const Problem& problem, const Case& c, double thr_opp);

}  // namespace foresight
