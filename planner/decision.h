// The decision in two steps (Mellmann & Schlotter, sec. IV): per kick choose the rotation around
// the ball, then choose among the optimised kicks. "Acceptable" means not trimmed (p_out <= T_out
// and no own-goal sample); "improves" means acceptable with a trimmed utility above that of
// `none` (leaving the ball where it is). Strategies (sec. IV-A):
//   fast          least rotation in both steps: per kick the least turn (either way; towards
//                 the opponent goal at equal turns) that makes it improve, then the kick with
//                 the least turn, ties to the higher utility. If no turn makes any kick improve,
//                 the least turn that makes one acceptable. The paper's robot "turns towards
//                 the goal"; a shorter turn the other way is taken here because the strategy's
//                 point is to turn least.
//   optimal_value best trimmed utility in both steps (ties: the least turn).
//   optimal_all   best trimmed utility per kick, then the kick needing the least rotation among
//                 the kicks that improve (if none improves: among the acceptable ones).
//   optimal_one   the forward kick only (the kick whose mean direction is closest to 0),
//                 rotated to its best trimmed utility.
//   naoth         NaoTH's published rule without rotation (planner/naoth_rule.h). When `none`
//                 wins the robot turns to face the opponent goal, as NaoTH's behaviour does.
// When no kick is acceptable at any rotation, every strategy but naoth falls back to the kick
// and rotation with the fewest own-goal samples, then the fewest outs, then the best utility,
// and says so in `note`.
#pragma once

#include <string>
#include <vector>

#include "planner/action_evaluator.h"
#include "planner/rotation_search.h"
#include "planner/strategy_names.h"

namespace foresight {

// Step 1's result for one kick.
struct KickOption {
  int kick_index = 0;
  bool considered = true;  // false: not used (optimal_one's side kicks, fast's hopeless kicks)
  bool no_acceptable_rotation = false;  // fast: no turn makes this kick acceptable
  RotationChoice choice;
};

struct Decision {
  Strategy strategy = Strategy::kOptimalValue;
  int kick_index = kNoKick;
  double rotation_rad = 0.0;
  std::vector<KickOption> kicks;  // one per kick of the model, in its order
  ActionEvaluation none;          // leaving the ball where it is
  std::string note;               // why a fallback was taken; empty normally
  long long evaluations = 0;      // hypotheses simulated
};

Decision Decide(ActionEvaluator& evaluator, Strategy strategy);
// The same into `out`, reusing its storage: with ReserveDecision done and the evaluator's
// scratch in place, a decision allocates nothing (tests/planner_alloc/).
void Decide(ActionEvaluator& evaluator, Strategy strategy, Decision& out);
// Room in `decision` for `kick_count` kicks and the longest note.
void ReserveDecision(Decision& decision, int kick_count);

}  // namespace foresight
