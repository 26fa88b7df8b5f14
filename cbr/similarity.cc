#include "cbr/similarity.h"

namespace foresight {

double BallSimilarity(const Problem& problem, const Case& c) {
  return ScopeGaussian(problem.p_F_ball - c.p_F_ball, c.ball_scope);
}

Vec2 MovedScopeCentre(const Problem& problem, const Case& c, const CaseOpponent& opponent) {
  return opponent.p_F - c.p_F_ball + problem.p_F_ball;
}

double OpponentScopeMembership(const Problem& problem, const Case& c, const CaseOpponent& opponent,
                               const Vec2& p_F) {
  return ScopeGaussian(p_F - MovedScopeCentre(problem, c, opponent), opponent.scope);
}

int OpponentSimilarity(const Problem& problem, const Case& c, double thr_opp) {
  int conditions = 0;
  const double limit = -std::log(thr_opp);  // Omega > thr_opp <=> exponent < -ln thr_opp
  for (const CaseOpponent& scope : c.opponents) {
    const Vec2 centre = MovedScopeCentre(problem, c, scope);
    for (const Vec2& o : problem.opponents) {
      const double u = (o.x() - centre.x()) / scope.scope.tau_x_m;
      const double v = (o.y() - centre.y()) / scope.scope.tau_y_m;
      if (u * u + v * v < limit) {
        ++conditions;
        break;
      }
    }
  }
  return conditions;
}

}  // namespace foresight
