// Symmetric copies: positions, headings and kicks mirror; passes keep their receivers; each
// transform is its own inverse.
#include "cbr/symmetry.h"

#include <gtest/gtest.h>

namespace foresight {
namespace {

const KickMirrors kMirrors{{"head_kick_left", "head_kick_right"},
                           {"head_kick_right", "head_kick_left"}};

CaseAction Action(ActionType type, const std::string& kick = "") {
  CaseAction a;
  a.type = type;
  a.kick = kick;
  return a;
}

Case PassCase() {
  Case c;
  c.name = c.source = "pass";
  c.p_F_ball = Vec2(1.3, 0.2);
  c.ball_scope = {0.45, 0.25};
  CaseAction get = Action(ActionType::kGetBall);
  CaseAction pass = Action(ActionType::kPass, "head_kick_left");
  pass.teammate = 2;
  CaseAction receive = Action(ActionType::kReceive);
  receive.teammate = 1;
  CaseAction turn = Action(ActionType::kTurn);
  turn.heading_rad = 0.5;
  CaseAction kick = Action(ActionType::kKick, "forward");
  kick.target_F = Vec2(2.7, -0.3);
  c.teammates = {{1, Vec2(1.0, 0.2), {get, pass}}, {2, Vec2(1.4, 1.0), {receive, turn, kick}}};
  c.opponents = {{1, Vec2(1.8, 0.2), {0.35, 0.3}}};
  return c;
}

TEST(SymmetryTest, MirrorYFlipsYAndHandsKeepsGoal) {
  const Case m = MirrorCase(PassCase(), CaseTransform::kMirrorY, kMirrors);
  EXPECT_EQ(m.name, "pass/mirror_y");
  EXPECT_EQ(m.source, "pass");
  EXPECT_EQ(m.defending, DefendingGoal::kCyan);
  EXPECT_EQ(m.p_F_ball, Vec2(1.3, -0.2));
  EXPECT_EQ(m.teammates[1].p_F, Vec2(1.4, -1.0));
  EXPECT_EQ(m.opponents[0].p_F, Vec2(1.8, -0.2));
  EXPECT_EQ(m.teammates[0].actions[1].kick, "head_kick_right");
  EXPECT_EQ(m.teammates[0].actions[1].teammate, 2);  // the receiver stays
  EXPECT_EQ(m.teammates[1].actions[0].teammate, 1);
  EXPECT_NEAR(*m.teammates[1].actions[1].heading_rad, -0.5, 1e-12);
  EXPECT_EQ(*m.teammates[1].actions[2].target_F, Vec2(2.7, 0.3));
  EXPECT_EQ(m.teammates[1].actions[2].kick, "forward");
  EXPECT_EQ(m.ball_scope.tau_x_m, 0.45);
  EXPECT_EQ(m.opponents[0].scope.tau_y_m, 0.3);
}

TEST(SymmetryTest, MirrorXTurnsToTheOtherGoalAndSwapsHands) {
  const Case m = MirrorCase(PassCase(), CaseTransform::kMirrorX, kMirrors);
  EXPECT_EQ(m.name, "pass/mirror_x");
  EXPECT_EQ(m.defending, DefendingGoal::kYellow);
  EXPECT_EQ(m.p_F_ball, Vec2(-1.3, 0.2));
  EXPECT_EQ(m.teammates[0].actions[1].kick, "head_kick_right");
  EXPECT_NEAR(*m.teammates[1].actions[1].heading_rad, kPi - 0.5, 1e-12);
}

TEST(SymmetryTest, MirrorXYTurnsToTheOtherGoalAndKeepsHands) {
  const Case m = MirrorCase(PassCase(), CaseTransform::kMirrorXY, kMirrors);
  EXPECT_EQ(m.name, "pass/mirror_xy");
  EXPECT_EQ(m.defending, DefendingGoal::kYellow);
  EXPECT_EQ(m.p_F_ball, Vec2(-1.3, -0.2));
  EXPECT_EQ(m.teammates[0].actions[1].kick, "head_kick_left");
  EXPECT_NEAR(*m.teammates[1].actions[1].heading_rad, 0.5 - kPi, 1e-12);
}

TEST(SymmetryTest, EachMirrorIsItsOwnInverse) {
  const Case c = PassCase();
  for (CaseTransform t :
       {CaseTransform::kMirrorY, CaseTransform::kMirrorX, CaseTransform::kMirrorXY}) {
    const Case back = MirrorCase(MirrorCase(c, t, kMirrors), t, kMirrors);
    EXPECT_EQ(back.name, "pass");
    EXPECT_EQ(back.transform, CaseTransform::kOriginal);
    EXPECT_EQ(back.defending, c.defending);
    EXPECT_EQ(back.p_F_ball, c.p_F_ball);
    EXPECT_EQ(back.teammates[1].p_F, c.teammates[1].p_F);
    EXPECT_EQ(back.teammates[0].actions[1].kick, "head_kick_left");
    EXPECT_NEAR(*back.teammates[1].actions[1].heading_rad, 0.5, 1e-12);
    EXPECT_EQ(*back.teammates[1].actions[2].target_F, Vec2(2.7, -0.3));
  }
  EXPECT_EQ(ComposeTransforms(CaseTransform::kMirrorX, CaseTransform::kMirrorY),
            CaseTransform::kMirrorXY);
  EXPECT_EQ(MirrorCase(MirrorCase(c, CaseTransform::kMirrorX, kMirrors), CaseTransform::kMirrorY,
                       kMirrors)
                .name,
            "pass/mirror_xy");
}

}  // namespace
}  // namespace foresight
