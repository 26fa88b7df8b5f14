// Ball and opponent similarity (sec. 3.1, 3.3.2): exp(-1) on the scope's edge; opponent scopes
// move with the ball (Fig. 2b).
#include "cbr/similarity.h"

#include <gtest/gtest.h>

#include <cmath>

namespace foresight {
namespace {

Case BallCase() {
  Case c;
  c.p_F_ball = Vec2(1.0, -0.5);
  c.ball_scope = {0.45, 0.25};  // Fig. 4's radii
  return c;
}

TEST(SimilarityTest, BallSimilarityIsOneAtTheCentreAndExpMinusOneOnTheEllipse) {
  const Case c = BallCase();
  Problem p;
  p.p_F_ball = c.p_F_ball;
  EXPECT_DOUBLE_EQ(BallSimilarity(p, c), 1.0);
  p.p_F_ball = c.p_F_ball + Vec2(0.45, 0.0);
  EXPECT_NEAR(BallSimilarity(p, c), std::exp(-1.0), 1e-12);
  p.p_F_ball = c.p_F_ball + Vec2(0.0, -0.25);
  EXPECT_NEAR(BallSimilarity(p, c), std::exp(-1.0), 1e-12);
  // On the ellipse at 45 degrees of the parameter: (tau_x cos t, tau_y sin t).
  p.p_F_ball = c.p_F_ball + Vec2(0.45 * std::cos(0.7), 0.25 * std::sin(0.7));
  EXPECT_NEAR(BallSimilarity(p, c), std::exp(-1.0), 1e-12);
  // By hand: dx = 0.225 (half tau_x), dy = 0.125 (half tau_y): exp(-(0.25 + 0.25)).
  p.p_F_ball = c.p_F_ball + Vec2(0.225, 0.125);
  EXPECT_NEAR(BallSimilarity(p, c), std::exp(-0.5), 1e-12);
}

TEST(SimilarityTest, OpponentScopesMoveWithTheBall) {
  Case c = BallCase();
  c.opponents.push_back({1, c.p_F_ball + Vec2(0.5, 0.0), {0.2, 0.1}});  // in front of the ball
  c.opponents.push_back({2, c.p_F_ball + Vec2(0.0, 0.8), {0.2, 0.2}});  // to the left
  Problem p;
  p.p_F_ball = c.p_F_ball + Vec2(0.3, 0.2);  // the ball moved within its scope
  EXPECT_EQ(MovedScopeCentre(p, c, c.opponents[0]), p.p_F_ball + Vec2(0.5, 0.0));
  // An opponent where the case had it (not moved) is 0.3 m behind the moved centre: outside.
  p.opponents = {c.opponents[0].p_F};
  EXPECT_NEAR(OpponentScopeMembership(p, c, c.opponents[0], p.opponents[0]),
              std::exp(-(1.5 * 1.5 + 2.0 * 2.0)), 1e-12);
  EXPECT_EQ(OpponentSimilarity(p, c, std::exp(-1.0)), 0);
  // In front of the moved ball: one condition; two opponents in the same scope still count once.
  p.opponents = {p.p_F_ball + Vec2(0.55, 0.02), p.p_F_ball + Vec2(0.45, -0.03)};
  EXPECT_EQ(OpponentSimilarity(p, c, std::exp(-1.0)), 1);
  p.opponents.push_back(p.p_F_ball + Vec2(0.1, 0.75));
  EXPECT_EQ(OpponentSimilarity(p, c, std::exp(-1.0)), 2);
  // Just inside and just outside the edge of scope 1 along x.
  p.opponents = {p.p_F_ball + Vec2(0.5 + 0.2 * 0.999, 0.0)};
  EXPECT_EQ(OpponentSimilarity(p, c, std::exp(-1.0)), 1);
  p.opponents = {p.p_F_ball + Vec2(0.5 + 0.2 * 1.001, 0.0)};
  EXPECT_EQ(OpponentSimilarity(p, c, std::exp(-1.0)), 0);
}

}  // namespace
}  // namespace foresight
