// Whether a case asks its kicks for rolls the robot's kicks give (planner/kick_reach.h). A case is
// knowledge for one robot's kicks: a shot the kick cannot carry to its target, or a pass that
// stops short of its receiver, is a plan the robots cannot play (the defender meets the ball
// where it stops). Each kick and pass of the case's ball path (cbr/free_path.h, played in the
// case's own situation, trajectories to their targets) is compared with the kick model:
//   beyond reach: its length l > d(z), the roll at z = reach_sigmas sd of the launch speed (the
//                 retrieval parameters' reach_sigmas; with z = 2 one kick in 44 rolls further);
//   pass short:   a pass whose mean roll E[d] does not carry the ball to the receiver's body,
//                 l - (R + r_b) > E[d] (R the robots' radius, r_b the ball's: the ball stops
//                 on touching the receiver, so it need not roll to its centre);
//   leaves field: a kick to a target (not a pass, not a shot: at the goal or at a target on the
//                 goal line) whose mean roll,
//                 launched z = reach_sigmas sd of its direction to either side of its aim, comes
//                 to rest beyond a side line (|y| > half_width_m): a plan that kicks the ball out
//                 about one time in 44 per side or more. Shots are left out: their aim is on the
//                 goal line, beside which a wide shot goes out whatever the plan.
// `foresight cbr check` reports all three and fails on them.
#pragma once

#include <string_view>
#include <vector>

#include "cbr/case.h"
#include "cbr/retrieval_params.h"
#include "models/kick_model.h"

namespace foresight {

enum class ReachFault { kBeyondReach, kPassShort, kLeavesField };
std::string_view ReachFaultName(ReachFault fault);

struct ReachFinding {
  ReachFault fault = ReachFault::kBeyondReach;
  int trajectory = -1;         // index along the case's ball path
  ActionType action = ActionType::kKick;  // kKick or kPass
  std::string kick;
  double length_m = 0.0;       // what the case asks
  double mean_roll_m = 0.0;    // E[d] of the kick
  double reach_m = 0.0;        // d(reach_sigmas)
  double out_m = 0.0;          // leaves field: how far beyond the side line the wider rest lies
};

// The faults of case `c` (empty when it is playable). Precondition: params.reach_sigmas is set
// (InputError otherwise) and every kick the case names is in `kicks`.
std::vector<ReachFinding> CheckCaseReach(const Case& c, const KickModel& kicks,
                                         const RetrievalParams& params);

// "pass head_kick_left (trajectory 0) of 1.10 m: the mean roll 0.64 m stops 0.30 m short of the
// receiver's body (reach 0.89 m at 2 sd)".
std::string DescribeFinding(const ReachFinding& f, const RetrievalParams& params);

}  // namespace foresight
