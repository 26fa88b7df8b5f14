// The decision in two steps (Mellmann & Schlotter, sec. IV): per kick choose the rotation around
// the ball, then choose among the optimised kicks. Strategies (sec. IV-A):
//   fast          least rotation in both steps: kick at once when some kick is acceptable and
//                 improves on leaving the ball; otherwise take the least turn that makes one
//                 so (towards the opponent goal when both ways need the same turn). The paper
//                 turns towards the goal; a shorter turn the other way is taken here because
//                 the strategy's point is to turn least.
//   optimal_value best trimmed utility in both steps.
//   optimal_all   best trimmed utility per kick, then the kick needing the least rotation.
//   optimal_one   the forward kick only (the kick whose mean direction is closest to 0),
//                 rotated to its best trimmed utility.
//   naoth         NaoTH's published rule, without rotation: drop kicks with an own-goal sample
//                 or an acceptable (infield + goal) share <= min_acceptable_share; prefer kicks
//                 with a goal share >= goal_preference_share, most goals first; otherwise the
//                 lowest mean potential, `none` included. When `none` wins the robot turns to
//                 face the opponent goal, as NaoTH's behaviour does.
// "Acceptable" means not trimmed (p_out <= T_out, no own goal); "improves" means a trimmed
// utility above that of `none`. When no kick is acceptable anywhere, the optimal strategies
// and fast fall back to the best untrimmed utility and say so in `note`.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "planner/action_evaluator.h"
#include "planner/rotation_search.h"

namespace foresight {

enum class Strategy { kFast, kOptimalValue, kOptimalAll, kOptimalOne, kNaoth };

std::string_view StrategyName(Strategy strategy);
std::optional<Strategy> ParseStrategy(std::string_view name);
std::vector<Strategy> AllStrategies();

// Step 1's result for one kick.
struct KickOption {
  int kick_index = 0;
  bool considered = true;  // false: the strategy does not use this kick (optimal_one)
  RotationChoice choice;
};

struct Decision {
  Strategy strategy = Strategy::kOptimalValue;
  int kick_index = -1;  // -1: none
  double rotation_rad = 0.0;
  std::vector<KickOption> kicks;  // one per kick of the model, in its order
  ActionEvaluation none;          // leaving the ball where it is
  std::string note;               // why a fallback was taken; empty normally
  long long evaluations = 0;      // hypotheses simulated
};

Decision Decide(ActionEvaluator& evaluator, Strategy strategy);

}  // namespace foresight
