// A case of case-based coordinated action selection (Ros, Arcos, López de Mántaras, Veloso,
// "A case-based approach for coordinated action selection in robot soccer", Artificial
// Intelligence 173 (2009), sec. 2): case = (P, A, K).
//   P, the problem: the ball B, the defending goal G, the teammates Tm (1-4, by id) and the
//      opponents Opp (0-4), all at global positions on the Four-Legged field;
//   A, the solution (a gameplay): one action sequence per teammate of P, such that (i) at least
//      one robot's first action is to get the ball and (ii) only one robot controls the ball at
//      a time;
//   K, the scope: ellipse radii (tau_x, tau_y) around the ball and around each case opponent.
//
// Frames and units: SI, the global field frame F of models/fields/four_legged.json (origin at
// the centre spot; the cyan goal at -x, the yellow goal at +x). A team defending cyan attacks
// towards +x. The paper writes millimetres; the case files give metres.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/geometry.h"

namespace foresight {

// The goal a team defends (the case base is indexed by it, sec. 3.4).
enum class DefendingGoal { kCyan, kYellow };

// An ellipse's radii, axis-aligned in F (sec. 2.3).
struct Scope {
  double tau_x_m = 0.0;
  double tau_y_m = 0.0;
};

enum class ActionType { kGetBall, kKick, kPass, kReceive, kGoTo, kTurn, kDribble, kWait };

// One action of a gameplay with its parameters (sec. 2.2). Which fields apply:
//   kGetBall, kWait: none;
//   kKick:    kick (a kick of the AIBO kick model) and either at_goal (aim at the centre of the
//             goal the team attacks) or target_F (a point);
//   kPass:    kick and teammate (the receiver's id);
//   kReceive: teammate (the passer's id);
//   kGoTo, kDribble: target_F;
//   kTurn:    heading_rad, or target_F (a point to face).
struct CaseAction {
  ActionType type = ActionType::kWait;
  std::string kick;
  bool at_goal = false;
  std::optional<Vec2> target_F;
  std::optional<double> heading_rad;
  int teammate = 0;
};

struct CaseTeammate {
  int id = 0;  // 1..4
  Vec2 p_F{0.0, 0.0};
  std::vector<CaseAction> actions;  // the teammate's part of the gameplay
};

struct CaseOpponent {
  int id = 0;
  Vec2 p_F{0.0, 0.0};
  Scope scope;
};

// How a stored case was made from a hand-written one (sec. 2.4).
enum class CaseTransform {
  kOriginal,  // as written
  kMirrorY,   // (x, y) -> (x, -y), same defending goal; left and right swap
  kMirrorX,   // (x, y) -> (-x, y), the other defending goal; left and right swap
  kMirrorXY,  // (x, y) -> (-x, -y), the other defending goal; left and right stay
};

struct Case {
  std::string name;  // unique in a case base; a copy is "<source>/<transform>"
  std::string notes;
  std::string source;  // the hand-written case's name (== name for kOriginal)
  CaseTransform transform = CaseTransform::kOriginal;
  DefendingGoal defending = DefendingGoal::kCyan;
  Vec2 p_F_ball{0.0, 0.0};
  Scope ball_scope;
  std::vector<CaseTeammate> teammates;  // by ascending id
  std::vector<CaseOpponent> opponents;
};

// Names as the case files and reports spell them ("cyan", "get_ball", "mirror_y"), from one
// table each (cbr/case.cc).
std::string_view DefendingGoalName(DefendingGoal goal);
std::optional<DefendingGoal> ParseDefendingGoal(std::string_view name);
std::string_view ActionTypeName(ActionType type);
std::optional<ActionType> ParseActionType(std::string_view name);
std::string ActionTypeNames();  // "get_ball, kick, ..." for messages
std::string_view CaseTransformName(CaseTransform transform);

// The case teammate (index into c.teammates) whose first action is get_ball, the first such in
// case order (sec. 2.2: "at least one robot has as its first action to get the ball"), or -1.
int BallGetter(const Case& c);

// A shot: a kick at the goal, or at a target on (or beyond) a goal line, |x| >= goal_x_m (the
// cases' far and near corners). Every other kick with a target is a kick into the field.
bool IsShot(const CaseAction& kick, double goal_x_m);

// The goal the team of `defending` attacks: yellow (+x) for cyan, cyan (-x) for yellow; +1 or -1.
double AttackSign(DefendingGoal defending);

}  // namespace foresight
