#include "cbr/case.h"

#include <cmath>

#include "common/enum_names.h"

namespace foresight {
namespace {

constexpr EnumNames<DefendingGoal, 2> kGoalNames{{{
    {DefendingGoal::kCyan, "cyan"},
    {DefendingGoal::kYellow, "yellow"},
}}};

constexpr EnumNames<ActionType, 8> kActionNames{{{
    {ActionType::kGetBall, "get_ball"},
    {ActionType::kKick, "kick"},
    {ActionType::kPass, "pass"},
    {ActionType::kReceive, "receive"},
    {ActionType::kGoTo, "go_to"},
    {ActionType::kTurn, "turn"},
    {ActionType::kDribble, "dribble"},
    {ActionType::kWait, "wait"},
}}};

constexpr EnumNames<CaseTransform, 4> kTransformNames{{{
    {CaseTransform::kOriginal, "original"},
    {CaseTransform::kMirrorY, "mirror_y"},
    {CaseTransform::kMirrorX, "mirror_x"},
    {CaseTransform::kMirrorXY, "mirror_xy"},
}}};

}  // namespace

std::string_view DefendingGoalName(DefendingGoal goal) {
  return kGoalNames.Name(goal);
}
std::optional<DefendingGoal> ParseDefendingGoal(std::string_view name) {
  return kGoalNames.Parse(name);
}
std::string_view ActionTypeName(ActionType type) {
  return kActionNames.Name(type);
}
std::optional<ActionType> ParseActionType(std::string_view name) {
  return kActionNames.Parse(name);
}
std::string ActionTypeNames() {
  return kActionNames.List();
}
std::string_view CaseTransformName(CaseTransform transform) {
  return kTransformNames.Name(transform);
}

int BallGetter(const Case& c) {
  for (std::size_t i = 0; i < c.teammates.size(); ++i) {
    const std::vector<CaseAction>& actions = c.teammates[i].actions;
    if (!actions.empty() && actions.front().type == ActionType::kGetBall) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

bool IsShot(const CaseAction& kick, double goal_x_m) {
  return kick.at_goal || (kick.target_F && std::abs(kick.target_F->x()) >= goal_x_m);
}

double AttackSign(DefendingGoal defending) {
  return defending == DefendingGoal::kCyan ? 1.0 : -1.0;
}

}  // namespace foresight
