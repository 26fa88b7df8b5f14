#include "experiments/passing_causes.h"

namespace foresight {

namespace {

// Adds the opponents' kicks of one trial: pairs each opponent kick event with the kick_end
// event after it.
void CountOpponentKicks(const MatchTrialResult& trial, double attack_sign, double min_moved_m,
                        ScenarioCauses& c) {
  const MatchEvent* kick = nullptr;
  for (const MatchEvent& e : trial.events) {
    if (e.kind == EventKind::kKick) kick = &e;
    if (e.kind != EventKind::kKickEnd || kick == nullptr) continue;
    if (kick->side == Side::kOpponents) {
      const Vec2 moved = e.p_F_ball - kick->p_F_ball;
      if (moved.norm() >= min_moved_m) {
        ++c.opponent_kicks_moved;
        c.opponent_kicks_own_goal += attack_sign * moved.x() > 0.0;
      }
    }
    kick = nullptr;
  }
}

void FillIntervals(double confidence, ScenarioCauses& c) {
  if (c.trials > 0) {
    c.to_goal_by_attackers_ci = WilsonInterval(c.to_goal_by_attackers, c.trials, confidence);
  }
  if (c.opponent_kicks_moved > 0) {
    c.opponent_kicks_own_goal_ci =
        WilsonInterval(c.opponent_kicks_own_goal, c.opponent_kicks_moved, confidence);
  }
}

}  // namespace

std::vector<ScenarioCauses> SummariseCauses(const PassingResult& result, const PassingSetup& setup,
                                            double confidence) {
  const double attack_sign = setup.mirrored ? -1.0 : 1.0;
  std::vector<ScenarioCauses> all;
  for (const ScenarioTrials& st : result.scenarios) {
    ScenarioCauses c;
    c.scenario = st.scenario;
    c.trials = static_cast<int>(st.trials.size());
    for (const MatchTrialResult& t : st.trials) {
      c.to_goal_by_attackers += IsToGoal(t.outcome) && t.counters.attacker_kick_sent;
      c.shots_on_target += t.counters.shots_on_target;
      c.shots_saved += t.counters.shots_saved;
      c.safety_cap_ended +=
          setup.config.time_limit_is_safety_cap && t.outcome == TrialOutcome::kTimeout;
      c.contests_resolved += t.counters.contests_resolved;
      c.stuck_penalties += t.counters.stuck_penalties;
      CountOpponentKicks(t, attack_sign, setup.params.kick_moved_min_m, c);
    }
    FillIntervals(confidence, c);
    all.push_back(c);
  }
  return all;
}

ScenarioCauses PoolCauses(const std::vector<ScenarioCauses>& scenarios, double confidence) {
  ScenarioCauses pooled;
  for (const ScenarioCauses& c : scenarios) {
    pooled.trials += c.trials;
    pooled.to_goal_by_attackers += c.to_goal_by_attackers;
    pooled.shots_on_target += c.shots_on_target;
    pooled.shots_saved += c.shots_saved;
    pooled.opponent_kicks_moved += c.opponent_kicks_moved;
    pooled.opponent_kicks_own_goal += c.opponent_kicks_own_goal;
    pooled.safety_cap_ended += c.safety_cap_ended;
    pooled.contests_resolved += c.contests_resolved;
    pooled.stuck_penalties += c.stuck_penalties;
  }
  FillIntervals(confidence, pooled);
  return pooled;
}

}  // namespace foresight
