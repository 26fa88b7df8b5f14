// Hand-made cases for the CBR team's tests: one robot gets the ball and kicks it to a target.
#pragma once

#include <string>

#include "cbr/case.h"

namespace foresight::testing {

// Case `name`: the ball at `p_F_ball` (scope 0.5 m), one teammate at `p_F_robot` that gets it
// and kicks `kick` to `target_F`.
inline Case GetAndKickCase(const std::string& name, const Vec2& p_F_ball, const Vec2& p_F_robot,
                           const std::string& kick, const Vec2& target_F) {
  CaseAction get, kick_action;
  get.type = ActionType::kGetBall;
  kick_action.type = ActionType::kKick;
  kick_action.kick = kick;
  kick_action.target_F = target_F;
  Case c;
  c.name = c.source = name;
  c.p_F_ball = p_F_ball;
  c.ball_scope = {0.5, 0.5};
  c.teammates = {{1, p_F_robot, {get, kick_action}}};
  return c;
}

}  // namespace foresight::testing
