// What the CBR team counts about itself for the experiments' tables (Ros et al. 2009, Table 3:
// cases retrieved per trial, individualistic vs cooperative; beyond it: cycles, "no case",
// aborts by reason, the robots' time in each state of Fig. 10). The experimenter's instruments:
// no robot reads them, so counting them in one place shares nothing between the robots.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "cbr/team_messages.h"
#include "models/team_policy.h"

namespace foresight {

// The states of the reuse FSM (Fig. 10) plus the two before a case is known.
enum class CbrPhase { kIdle, kAwaitCase, kAdapt, kExecute, kWaitEnd };
inline constexpr int kCbrPhaseCount = 5;
std::string_view CbrPhaseName(CbrPhase phase);

struct CbrTeamCounters {
  int cycles = 0;
  int retrieved = 0;
  int individual = 0;
  int cooperative = 0;
  int no_case = 0;
  int timing_rejected = 0;  // candidates the timing-aware pass check turned down
  int race_lost = 0;        // retrievals refused: an opponent reaches the ball first
  int race_skipped = 0;     // candidates whose getter could not be the team's fastest robot
  int kick_race_lost = 0;   // candidates whose getter would not play the ball away in time
  int blocked_skipped = 0;  // candidates passed over: given up for a blocked path, same ball
  // Why "no case", by the furthest any case got through Algorithm 1: a candidate the team turned
  // down (race or pass timing), a path blocked, robots too far, no ball in a scope.
  int no_case_candidates_refused = 0;
  int no_case_path_blocked = 0;
  int no_case_too_far = 0;
  int no_case_out_of_scope = 0;
  // Cases whose robots make two kicks or more between them (a pass and the kick after it), and
  // those the coordinator saw every robot finish (END); likewise all cases.
  int multi_kick = 0;
  int multi_kick_completed = 0;
  int completed = 0;
  // Robots of a case that stopped waiting for a teammate still executing (the safety net).
  int wait_end_timeouts = 0;
  std::array<int, kAbortReasonCount> aborts{};  // cycles aborted, by the first reason
  int last_aborted_cycle = -1;
  std::array<double, kCbrPhaseCount> phase_time_s{};  // summed over the robots
  // Of the idle (default behaviour) time: while the ball rolled faster than the robots walk (no
  // cycle starts then, cbr/ball_race.h) and while an opponent touched it (ball lost).
  double idle_ball_rolling_s = 0.0;
  double idle_opponent_on_ball_s = 0.0;

  void CountCase(int teammates, int kicks);
  void CountCompleted(int kicks);
  // Once per cycle: two robots may find the case inapplicable in the same step.
  void CountAbort(int cycle, AbortReason reason);
  // "cycles", "cases_retrieved", ..., "aborts_ball_lost", ..., "robot_time_adapt_s", ...
  std::vector<TeamPolicy::Counter> List() const;
};

}  // namespace foresight
