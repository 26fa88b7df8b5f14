#include "planner/naoth_rule.h"

#include <cmath>

namespace foresight {

namespace {

bool Passes(const NaothRuleParams& params, const ActionEvaluation& e) {
  if (e.Count(Category::kOwnGoal) > 0) return false;
  return e.p_infield + e.p_opp_goal > params.min_acceptable_share;
}

}  // namespace

NaothChoice ApplyNaothRule(const NaothRuleParams& params, const std::vector<KickOption>& kicks,
                           const ActionEvaluation& none) {
  const KickOption* goal_kick = nullptr;
  for (const KickOption& k : kicks) {
    const ActionEvaluation& e = k.choice.evaluation;
    if (!Passes(params, e) || e.p_opp_goal < params.goal_preference_share) continue;
    if (goal_kick == nullptr) {
      goal_kick = &k;
      continue;
    }
    const ActionEvaluation& g = goal_kick->choice.evaluation;
    const int goals = e.Count(Category::kOppGoal), best_goals = g.Count(Category::kOppGoal);
    if (goals > best_goals || (goals == best_goals && e.potential_all_avg < g.potential_all_avg))
      goal_kick = &k;
  }
  if (goal_kick != nullptr) return {goal_kick->kick_index};

  NaothChoice choice;  // `none` unless a kick has a lower mean potential
  double best_potential =
      Passes(params, none) && none.Count(Category::kInfield) > 0 ? none.potential_avg : INFINITY;
  for (const KickOption& k : kicks) {
    const ActionEvaluation& e = k.choice.evaluation;
    if (!Passes(params, e) || e.Count(Category::kInfield) == 0) continue;
    if (e.potential_avg < best_potential) {
      best_potential = e.potential_avg;
      choice.kick_index = k.kick_index;
    }
  }
  return choice;
}

double FaceGoalRotation(const FieldSpec& field, const StateEstimate& state) {
  const Vec2 to_goal = Vec2(field.HalfLength(), 0.0) - state.MeanBallInField();
  return WrapAngle(std::atan2(to_goal.y(), to_goal.x()) - state.robot.theta_rad);
}

}  // namespace foresight
