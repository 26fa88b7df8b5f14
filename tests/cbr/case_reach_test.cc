// A case's kicks against the kick model (cbr/case_reach.h): the lengths along the case's own ball
// path, the reach at z sd and the pass that stops short, at their exact edges.
#include "cbr/case_reach.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "planner/kick_reach.h"

namespace foresight {
namespace {

KickModel Kicks() {
  KickModel m;
  m.robot = "test";
  m.rolling_deceleration_mps2 = 0.25;
  m.kicks = {{"forward", 1.0, 0.1, 0.0, 0.1, 0.0}, {"head_kick_left", 0.5, 0.05, kPi / 2, 0.05, 0.0}};
  return m;
}

RetrievalParams Params() {
  RetrievalParams p;
  p.reach_sigmas = 2.0;
  p.opponent_radius_m = 0.12;
  p.ball_radius_m = 0.04;
  return p;
}

// One robot at (0, 0) with the ball at (0.3, 0): a kick to (0.3 + length, 0).
Case Shot(double length_m) {
  Case c;
  c.name = "shot";
  c.p_F_ball = Vec2(0.3, 0.0);
  CaseAction get, kick;
  get.type = ActionType::kGetBall;
  kick.type = ActionType::kKick;
  kick.kick = "forward";
  kick.target_F = Vec2(0.3 + length_m, 0.0);
  c.teammates.push_back({1, Vec2(0.0, 0.0), {get, kick}});
  return c;
}

// A head-kick pass from the ball at (0.3, 0) to a receiver `length_m` to its left.
Case Pass(double length_m) {
  Case c;
  c.name = "pass";
  c.p_F_ball = Vec2(0.3, 0.0);
  CaseAction get, pass, receive;
  get.type = ActionType::kGetBall;
  pass.type = ActionType::kPass;
  pass.kick = "head_kick_left";
  pass.teammate = 2;
  receive.type = ActionType::kReceive;
  receive.teammate = 1;
  c.teammates.push_back({1, Vec2(0.0, 0.0), {get, pass}});
  c.teammates.push_back({2, Vec2(0.3, length_m), {receive}});
  return c;
}

TEST(CaseReachTest, AKickFitsUpToItsReachAndNoFurther) {
  const double reach = RollDistanceAtSigmas(Kicks().kicks[0], 0.25, 2.0);  // 1.2^2 / 0.5 = 2.88
  EXPECT_NEAR(reach, 2.88, 1e-12);
  EXPECT_TRUE(CheckCaseReach(Shot(reach - 1e-6), Kicks(), Params()).empty());
  const std::vector<ReachFinding> f = CheckCaseReach(Shot(reach + 1e-6), Kicks(), Params());
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].fault, ReachFault::kBeyondReach);
  EXPECT_EQ(f[0].kick, "forward");
  EXPECT_NEAR(f[0].length_m, reach, 1e-5);
  EXPECT_NEAR(f[0].mean_roll_m, (1.0 + 0.01) / 0.5, 1e-12);
}

TEST(CaseReachTest, APassMustCarryToTheReceiversBody) {
  // Mean roll (0.25 + 0.0025) / 0.5 = 0.505 m; the ball stops on the body 0.16 m before the
  // receiver's centre, so the pass may be 0.665 m long; the reach is 0.6^2 / 0.5 = 0.72 m.
  EXPECT_TRUE(CheckCaseReach(Pass(0.664), Kicks(), Params()).empty());
  std::vector<ReachFinding> f = CheckCaseReach(Pass(0.666), Kicks(), Params());
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].fault, ReachFault::kPassShort);
  EXPECT_EQ(f[0].action, ActionType::kPass);
  f = CheckCaseReach(Pass(0.73), Kicks(), Params());
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].fault, ReachFault::kBeyondReach);  // beyond reach is said first
  EXPECT_EQ(DescribeFinding(f[0], Params()),
            "pass head_kick_left (trajectory 0) of 0.73 m is beyond the kick's reach 0.72 m at 2 "
            "sd (mean roll 0.51 m)");
}

// A kick along +x from (0.3, y0): mean roll (1 + 0.01) / 0.5 = 2.02 m; launched 2 sd (0.2 rad) to
// the left it rests at y0 + 2.02 sin 0.2 = y0 + 0.4013, inside the side line (1.8 m) up to
// y0 = 1.3987.
Case KickUpTheWing(double y0, double target_x_m) {
  Case c = Shot(1.0);
  c.p_F_ball = Vec2(0.3, y0);
  c.teammates[0].p_F = Vec2(0.0, y0);
  c.teammates[0].actions[1].target_F = Vec2(target_x_m, y0);
  return c;
}

TEST(CaseReachTest, AKickWhoseWideLaunchRestsBeyondTheSideLineFails) {
  EXPECT_TRUE(CheckCaseReach(KickUpTheWing(1.39, 2.3), Kicks(), Params()).empty());
  const std::vector<ReachFinding> f = CheckCaseReach(KickUpTheWing(1.41, 2.3), Kicks(), Params());
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].fault, ReachFault::kLeavesField);
  EXPECT_NEAR(f[0].out_m, 1.41 + 2.02 * std::sin(0.2) - 1.8, 1e-12);
  EXPECT_EQ(DescribeFinding(f[0], Params()),
            "kick forward (trajectory 0): launched 2 sd of its direction off its aim, its mean "
            "roll 2.02 m rests 0.01 m beyond the side line");
  // The same kick at a target on the goal line is a shot: a wide shot goes out whatever the plan.
  EXPECT_TRUE(CheckCaseReach(KickUpTheWing(1.41, 2.7), Kicks(), Params()).empty());
}

TEST(CaseReachTest, AKickAtTheSideLineIsJudgedByItsWidestRestNotItsEnds) {
  // Aimed straight at the side line (+y) from y0 = 1.0 with a 0.5 rad sd: the spread's ends
  // (+-1 rad) rest 2.02 sin(0.57) = 1.10 m further out, the straight kick 2.02 m.
  KickModel wide = Kicks();
  wide.kicks[0].sigma_direction_rad = 0.5;
  Case c = KickUpTheWing(1.0, 0.3);
  c.teammates[0].p_F = Vec2(0.3, 0.7);
  c.teammates[0].actions[1].target_F = Vec2(0.3, 1.5);
  const std::vector<ReachFinding> f = CheckCaseReach(c, wide, Params());
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NEAR(f[0].out_m, 1.0 + 2.02 - 1.8, 1e-12);
}

TEST(CaseReachTest, TheCheckNeedsAReach) {
  RetrievalParams p = Params();
  p.reach_sigmas.reset();
  EXPECT_THROW(CheckCaseReach(Shot(1.0), Kicks(), p), InputError);
}

}  // namespace
}  // namespace foresight
