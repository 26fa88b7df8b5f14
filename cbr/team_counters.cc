#include "cbr/team_counters.h"

#include <string>

namespace foresight {

std::string_view CbrPhaseName(CbrPhase phase) {
  constexpr std::string_view kNames[] = {"idle", "await_case", "adapt", "execute", "wait_end"};
  return kNames[static_cast<int>(phase)];
}

void CbrTeamCounters::CountCase(int teammates, int kicks) {
  ++retrieved;
  ++(teammates >= 2 ? cooperative : individual);
  multi_kick += kicks >= 2;
}

void CbrTeamCounters::CountCompleted(int kicks) {
  ++completed;
  multi_kick_completed += kicks >= 2;
}

void CbrTeamCounters::CountAbort(int cycle, AbortReason reason) {
  if (cycle != last_aborted_cycle) ++aborts[static_cast<std::size_t>(reason)];
  last_aborted_cycle = cycle;
}

std::vector<TeamPolicy::Counter> CbrTeamCounters::List() const {
  std::vector<TeamPolicy::Counter> c = {{"cycles", static_cast<double>(cycles)},
                                        {"cases_retrieved", static_cast<double>(retrieved)},
                                        {"cases_individual", static_cast<double>(individual)},
                                        {"cases_cooperative", static_cast<double>(cooperative)},
                                        {"no_case", static_cast<double>(no_case)},
                                        {"timing_rejected", static_cast<double>(timing_rejected)},
                                        {"race_lost", static_cast<double>(race_lost)},
                                        {"race_skipped", static_cast<double>(race_skipped)},
                                        {"blocked_skipped", static_cast<double>(blocked_skipped)},
                                        {"kick_race_lost", static_cast<double>(kick_race_lost)},
                                        {"no_case_candidates_refused",
                                         static_cast<double>(no_case_candidates_refused)},
                                        {"no_case_path_blocked", static_cast<double>(no_case_path_blocked)},
                                        {"no_case_too_far", static_cast<double>(no_case_too_far)},
                                        {"no_case_out_of_scope", static_cast<double>(no_case_out_of_scope)},
                                        {"cases_completed", static_cast<double>(completed)},
                                        {"cases_multi_kick", static_cast<double>(multi_kick)},
                                        {"cases_multi_kick_completed",
                                         static_cast<double>(multi_kick_completed)},
                                        {"wait_end_timeouts", static_cast<double>(wait_end_timeouts)},
                                        {"robot_time_idle_ball_rolling_s", idle_ball_rolling_s},
                                        {"robot_time_idle_opponent_on_ball_s",
                                         idle_opponent_on_ball_s}};
  for (int i = 0; i < kAbortReasonCount; ++i) {
    c.push_back({"aborts_" + std::string(AbortReasonName(static_cast<AbortReason>(i))),
                 static_cast<double>(aborts[static_cast<std::size_t>(i)])});
  }
  for (int i = 0; i < kCbrPhaseCount; ++i) {
    c.push_back({"robot_time_" + std::string(CbrPhaseName(static_cast<CbrPhase>(i))) + "_s",
                 phase_time_s[static_cast<std::size_t>(i)]});
  }
  return c;
}

}  // namespace foresight
