// Whether a case asks a robot to hold the ball longer than the rules let it (the ball-holding
// rule: RoboCup Four-Legged League 2007, at most 3 s; models/match/simulation.json). A case is
// knowledge for one robot: a dribble and the turns before a kick that take longer than the holding
// limit are a plan the robot cannot play (the rule kicks the ball away first, unaimed, and the
// team's actions cut the dribble short, cbr/case_actions.h). Each kick and pass of the case's ball
// path (cbr/free_path.h, in the case's own situation) is timed with PlanHold (cbr/kick_race.h):
// from the moment its kicker holds the ball (after get_ball: facing the ball from its case
// position; after receive: facing the pass's start) through its turns and dribbles with the ball
// to the aimed kick; the case fails when that time exceeds hold_limit_s.
// `foresight cbr check` reports these with the reach faults (cbr/case_reach.h) and fails on them.
#pragma once

#include <string>
#include <vector>

#include "cbr/case.h"
#include "cbr/kick_race.h"
#include "cbr/retrieval_params.h"
#include "models/kick_model.h"

namespace foresight {

struct HoldingFinding {
  int trajectory = -1;  // index along the case's ball path
  int teammate = 0;     // the kicker's case teammate id
  std::string kick;
  double hold_s = 0.0;
  double dribble_m = 0.0;
  double turns_rad = 0.0;
};

// The kicks of case `c` whose kicker holds the ball longer than hold.hold_limit_s (empty when
// every one fits). Precondition: every kick the case names is in `kicks`.
std::vector<HoldingFinding> CheckCaseHolding(const Case& c, const KickModel& kicks,
                                             const RetrievalParams& params, const HoldParams& hold);

// "teammate 1 holds the ball 8.29 s before its kick forward (trajectory 0): dribbles 0.67 m at
// 0.15 m/s and turns 172 deg at 45 deg/s, beyond the ball-holding limit 2.70 s".
std::string DescribeFinding(const HoldingFinding& f, const HoldParams& hold);

}  // namespace foresight
