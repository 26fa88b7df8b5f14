// How long a case asks its robots to hold the ball (cbr/case_holding.h): the getter's dribble and
// turns, a receiver who faces the pass and turns to shoot, at their exact edges.
#include "cbr/case_holding.h"

#include <gtest/gtest.h>

#include <cmath>

namespace foresight {
namespace {

// grab 0.3 s, dribble 0.15 m/s, turn with the ball 45 deg/s, limit 2.7 s, launch 0.3 s.
const HoldParams kHold{0.3, 0.15, kPi / 4.0, 2.7, 0.3};

KickModel Kicks() {
  KickModel m;
  m.robot = "test";
  m.kicks = {{"forward", 1.0, 0.1, 0.0, 0.1, 0.0}, {"head_kick_left", 0.5, 0.05, kPi / 2, 0.05, 0.0}};
  return m;
}

CaseAction Act(ActionType type, const std::string& kick = "") {
  CaseAction a;
  a.type = type;
  a.kick = kick;
  return a;
}

// The getter behind the ball at the origin dribbles `dribble_m` straight on, then kicks at a
// target `aim_deg` off its heading.
Case Dribble(double dribble_m, double aim_deg) {
  Case c;
  c.name = "dribble";
  c.p_F_ball = Vec2(0.0, 0.0);
  CaseAction dribble = Act(ActionType::kDribble);
  dribble.target_F = Vec2(dribble_m, 0.0);
  CaseAction kick = Act(ActionType::kKick, "forward");
  kick.target_F = Vec2(dribble_m, 0.0) + 1.5 * UnitVector(aim_deg * kDegToRad);
  c.teammates.push_back({1, Vec2(-0.3, 0.0), {Act(ActionType::kGetBall), dribble, kick}});
  return c;
}

TEST(CaseHoldingTest, ADribbleAndAnAimWithinTheLimitPass) {
  // 0.3 m at 0.15 m/s (2 s) and a 30 deg aim (0.67 s): 2.67 s <= 2.7 s.
  EXPECT_TRUE(CheckCaseHolding(Dribble(0.3, 30.0), Kicks(), RetrievalParams{}, kHold).empty());
}

TEST(CaseHoldingTest, TheSameDribbleWithAWiderAimFailsWithItsFigures) {
  // 2 s of dribble and a 45 deg aim (1 s): 3 s > 2.7 s.
  const std::vector<HoldingFinding> f =
      CheckCaseHolding(Dribble(0.3, 45.0), Kicks(), RetrievalParams{}, kHold);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].teammate, 1);
  EXPECT_EQ(f[0].trajectory, 0);
  EXPECT_EQ(f[0].kick, "forward");
  EXPECT_NEAR(f[0].hold_s, 3.0, 1e-9);
  EXPECT_NEAR(f[0].dribble_m, 0.3, 1e-12);
  EXPECT_NEAR(f[0].turns_rad, kPi / 4.0, 1e-9);
  EXPECT_EQ(DescribeFinding(f[0], kHold),
            "teammate 1 holds the ball 3.00 s before its kick forward (trajectory 0): dribbles "
            "0.30 m at 0.15 m/s and turns 45 deg at 45 deg/s, beyond the ball-holding limit "
            "2.70 s");
}

// A head-kick pass to the left to a receiver 0.75 m away, who shoots `shot_deg` off +x.
Case PassAndShoot(double shot_deg) {
  Case c;
  c.name = "pass";
  c.p_F_ball = Vec2(0.0, 0.0);
  CaseAction pass = Act(ActionType::kPass, "head_kick_left");
  pass.teammate = 2;
  CaseAction receive = Act(ActionType::kReceive);
  receive.teammate = 1;
  CaseAction shot = Act(ActionType::kKick, "forward");
  shot.target_F = Vec2(0.0, 0.75) + 2.0 * UnitVector(shot_deg * kDegToRad);
  c.teammates.push_back({1, Vec2(-0.3, 0.0), {Act(ActionType::kGetBall), pass}});
  c.teammates.push_back({2, Vec2(0.0, 0.75), {receive, shot}});
  return c;
}

TEST(CaseHoldingTest, AReceiverFacesThePassAndTurnsToShoot) {
  // The pass runs along +y: the receiver faces -y (-90 deg). A shot along +x is a quarter turn
  // (2 s); one 30 deg to the right of it (-30 deg) is 60 deg (1.33 s); one 30 deg left, 120 deg
  // (2.67 s): all fit. A shot back along the pass's own direction (+y, 90 deg) is a half turn.
  for (double shot : {0.0, -30.0, 30.0}) {
    EXPECT_TRUE(CheckCaseHolding(PassAndShoot(shot), Kicks(), RetrievalParams{}, kHold).empty())
        << shot;
  }
  const std::vector<HoldingFinding> f =
      CheckCaseHolding(PassAndShoot(90.0), Kicks(), RetrievalParams{}, kHold);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].teammate, 2);
  EXPECT_EQ(f[0].trajectory, 1);
  EXPECT_NEAR(f[0].hold_s, 4.0, 1e-9);
  // The passer's own hold: it walked from (-0.3, 0) along +x and its head kick leaves 90 deg to
  // its left, along +y, where the pass goes: no turn, not reported.
}

}  // namespace
}  // namespace foresight
