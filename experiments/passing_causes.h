// Who caused a trial's end, and where the opponents' kicks went, from each trial's counters and
// event log (match/trial_result.h): the measures that tell whether the attackers earned an
// outcome or the world handed it to them.
//  - to goal by the attackers: a "to goal" trial (goal, close, penalty area) whose last kick was
//    an attacker's with no opponent touching the ball after it;
//  - shots on target and saves: attackers' kicks whose unobstructed roll would have entered the
//    attacked goal, and how many of them the goalie touched before their travel ended (the
//    paper's "block": the goalie stops or kicks the ball, sec. 5.1.4);
//  - the opponents' kicks that moved the ball at least min_moved_m (from the kick event to its
//    kick_end event: rest, a body, a grab or the end) and how many of those moved it towards
//    their own goal (the displacement's component along the attack direction is positive);
//  - the trials the configuration's safety cap ended (a time limit the paper does not have);
//  - how often the referee set down a ball both teams fought over too long.
#pragma once

#include <vector>

#include "experiments/passing.h"
#include "stats/statistics.h"

namespace foresight {

struct ScenarioCauses {
  int scenario = 0;
  int trials = 0;
  int to_goal_by_attackers = 0;
  Interval to_goal_by_attackers_ci;  // Wilson, of the share of all trials
  int shots_on_target = 0;
  int shots_saved = 0;
  int opponent_kicks_moved = 0;     // moved the ball at least min_moved_m
  int opponent_kicks_own_goal = 0;  // of those, towards the opponents' own goal
  Interval opponent_kicks_own_goal_ci;  // Wilson, of the share of the moved kicks
  int safety_cap_ended = 0;         // 0 unless the time limit is a safety cap
  int contests_resolved = 0;        // the referee's contest rule fired (match/match.h)
  int stuck_penalties = 0;          // the referee called local game stuck (match/match.h)
};

std::vector<ScenarioCauses> SummariseCauses(const PassingResult& result, const PassingSetup& setup,
                                            double confidence);

// All scenarios' counts added up (scenario 0), with the intervals of the sums: the experiment's
// figure for a share whose per-scenario counts are small (a few dozen long opponent kicks).
ScenarioCauses PoolCauses(const std::vector<ScenarioCauses>& scenarios, double confidence);

}  // namespace foresight
