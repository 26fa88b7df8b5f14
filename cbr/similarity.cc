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
  for (const CaseOpponent& scope : c.opponents) {
    for (const Vec2& o : problem.opponents) {
      if (OpponentScopeMembership(problem, c, scope, o) > thr_opp) {
        ++conditions;
        break;
      }
    }
  }
  return conditions;
}

}  // namespace foresight
