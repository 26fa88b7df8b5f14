// NaoTH's published kick rule (Mellmann, Schlotter & Blum, RoboCup 2016), kept for comparison
// with the strategies of the 2017 paper. Applied to kicks evaluated without rotation:
//   1. drop kicks with any own-goal sample or an acceptable share (infield + opponent goal)
//      <= min_acceptable_share;
//   2. if some remaining kick has a goal share >= goal_preference_share, take the one with the
//      most goal samples; on a tie, the lowest mean potential over all samples, goal samples
//      included (ActionEvaluation::potential_all_avg), as NaoTH's own implementation
//      does;
//   3. otherwise take the lowest mean potential among the remaining kicks and `none` (which
//      passes the same filter). This mean is over the infield samples only: below the goal
//      preference goal samples do not count.
#pragma once

#include <vector>

#include "models/evaluation_params.h"
#include "models/situation.h"
#include "planner/decision.h"

namespace foresight {

struct NaothChoice {
  int kick_index = kNoKick;
};

NaothChoice ApplyNaothRule(const NaothRuleParams& params, const std::vector<KickOption>& kicks,
                           const ActionEvaluation& none);

// The turn that makes the robot face the opponent goal's centre from the ball, in (-pi, pi].
double FaceGoalRotation(const FieldSpec& field, const StateEstimate& state);
inline double FaceGoalRotation(const Situation& situation) {
  return FaceGoalRotation(situation.field, situation.state);
}

}  // namespace foresight
