// A case played in its own situation (cbr/own_situation.h).
#include "cbr/own_situation.h"

#include <gtest/gtest.h>

namespace foresight {
namespace {

// One attacker at (1.0, 0.0) behind the ball at (1.3, 0.0) kicks at the yellow goal (2.7, 0).
Case KickAtGoal() {
  Case c;
  c.name = "kick";
  c.source = "kick";
  c.defending = DefendingGoal::kCyan;
  c.p_F_ball = Vec2(1.3, 0.0);
  c.ball_scope = {0.4, 0.4};
  CaseAction get;
  get.type = ActionType::kGetBall;
  CaseAction kick;
  kick.type = ActionType::kKick;
  kick.kick = "forward";
  kick.at_goal = true;
  c.teammates.push_back({1, Vec2(1.0, 0.0), {get, kick}});
  return c;
}

TEST(OwnSituationTest, OwnProblemIsTheCaseWithTeammatesFacingTheAttackedGoal) {
  Case c = KickAtGoal();
  c.opponents.push_back({1, Vec2(2.0, 1.0), {0.3, 0.3}});
  const Problem p = CaseOwnProblem(c);
  EXPECT_EQ(p.p_F_ball, c.p_F_ball);
  EXPECT_EQ(p.defending, DefendingGoal::kCyan);
  ASSERT_EQ(p.teammates.size(), 1u);
  EXPECT_EQ(p.teammates[0].id, 1);
  EXPECT_EQ(p.teammates[0].pose.p_F, Vec2(1.0, 0.0));
  EXPECT_EQ(p.teammates[0].pose.theta_rad, 0.0);
  ASSERT_EQ(p.opponents.size(), 1u);
  EXPECT_EQ(p.opponents[0], Vec2(2.0, 1.0));
  c.defending = DefendingGoal::kYellow;
  EXPECT_DOUBLE_EQ(CaseOwnProblem(c).teammates[0].pose.theta_rad, kPi);
}

TEST(OwnSituationTest, AnOpponentOnTheCasesOwnKickBlocksIt) {
  const RetrievalParams params;
  Case c = KickAtGoal();
  const CaseBallPath path = OwnBallPath(c, params);
  ASSERT_EQ(path.count, 1);
  EXPECT_EQ(path.trajectories[0].start_F, Vec2(1.3, 0.0));
  EXPECT_NEAR(path.trajectories[0].end_F.x(), params.goal_x_m, 1e-12);
  EXPECT_TRUE(OwnPathCheck(c, params).free);

  c.opponents.push_back({1, Vec2(2.0, 1.0), {0.3, 0.3}});  // off the line
  EXPECT_TRUE(OwnPathCheck(c, params).free);
  c.opponents.push_back({2, Vec2(2.45, 0.0), {0.2, 0.4}});  // a goalie on the line
  const PathCheck blocked = OwnPathCheck(c, params);
  EXPECT_FALSE(blocked.free);
  EXPECT_EQ(blocked.opponent, 1);
  EXPECT_EQ(blocked.trajectory, 0);
  EXPECT_GT(blocked.membership, params.thr_trajectory);
}

}  // namespace
}  // namespace foresight
