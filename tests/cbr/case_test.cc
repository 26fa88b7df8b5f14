// The case vocabulary: names round-trip, the attack direction of each defending goal.
#include "cbr/case.h"

#include <gtest/gtest.h>

namespace foresight {
namespace {

TEST(CaseTest, NamesRoundTrip) {
  for (ActionType t :
       {ActionType::kGetBall, ActionType::kKick, ActionType::kPass, ActionType::kReceive,
        ActionType::kGoTo, ActionType::kTurn, ActionType::kDribble, ActionType::kWait}) {
    EXPECT_EQ(ParseActionType(ActionTypeName(t)), t);
  }
  EXPECT_EQ(ParseDefendingGoal("yellow"), DefendingGoal::kYellow);
  EXPECT_FALSE(ParseDefendingGoal("blue").has_value());
  EXPECT_EQ(CaseTransformName(CaseTransform::kMirrorXY), "mirror_xy");
  EXPECT_EQ(ActionTypeNames(), "get_ball, kick, pass, receive, go_to, turn, dribble, wait");
}

TEST(CaseTest, CyanDefendersAttackTowardsPlusX) {
  EXPECT_EQ(AttackSign(DefendingGoal::kCyan), 1.0);
  EXPECT_EQ(AttackSign(DefendingGoal::kYellow), -1.0);
}

}  // namespace
}  // namespace foresight
