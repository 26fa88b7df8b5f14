#include "experiments/passing_stats.h"

namespace foresight {

MeanStat SummariseValues(const std::vector<double>& values, double confidence) {
  MeanStat s;
  s.n = static_cast<int>(values.size());
  if (s.n == 0) return s;
  const MeanSd m = SampleMeanSd(values);
  s.mean = m.mean;
  s.sd = s.n >= 2 ? m.sd : 0.0;
  s.ci = s.n >= 2 ? MeanTInterval(values, confidence) : Interval{m.mean, m.mean};
  return s;
}

namespace {

std::vector<MeanStat> PerRobot(const std::vector<MatchTrialResult>& trials, bool skip_timeouts,
                               double confidence,
                               const std::vector<int>& (*counter)(const TrialCounters&)) {
  std::vector<std::vector<double>> values;
  for (const MatchTrialResult& t : trials) {
    if (skip_timeouts && t.outcome == TrialOutcome::kTimeout) continue;
    const std::vector<int>& c = counter(t.counters);
    values.resize(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) values[i].push_back(c[i]);
  }
  std::vector<MeanStat> stats;
  for (const auto& v : values) stats.push_back(SummariseValues(v, confidence));
  return stats;
}

const std::vector<int>& Touches(const TrialCounters& c) {
  return c.opponent_touches;
}
const std::vector<int>& OpponentKicks(const TrialCounters& c) {
  return c.opponent_kicks;
}
const std::vector<int>& Backups(const TrialCounters& c) {
  return c.attacker_backups;
}

ScenarioSummary Summarise(const ScenarioTrials& st, double confidence) {
  ScenarioSummary s;
  s.scenario = st.scenario;
  s.name = st.name;
  s.trials = static_cast<int>(st.trials.size());
  std::vector<double> times, times_ended;
  for (const MatchTrialResult& t : st.trials) {
    ++s.counts[static_cast<std::size_t>(t.outcome)];
    s.to_goal += IsToGoal(t.outcome);
    times.push_back(t.counters.time_s);
    s.kicks_missed += t.counters.kicks_missed;
    s.kicks_not_settled += t.counters.kicks_not_settled;
    s.kicks_fell += t.counters.kicks_fell;
    s.kicks_blocked += t.counters.kicks_blocked;
    if (t.outcome != TrialOutcome::kTimeout) times_ended.push_back(t.counters.time_s);
  }
  for (int k = 0; k < kTrialOutcomeCount; ++k) {
    s.shares_ci[static_cast<std::size_t>(k)] =
        WilsonInterval(s.counts[static_cast<std::size_t>(k)], s.trials, confidence);
  }
  s.to_goal_ci = WilsonInterval(s.to_goal, s.trials, confidence);
  s.possession = PerRobot(st.trials, false, confidence, Touches);
  s.possession_ended = PerRobot(st.trials, true, confidence, Touches);
  s.opponent_kicks = PerRobot(st.trials, false, confidence, OpponentKicks);
  s.backups = PerRobot(st.trials, false, confidence, Backups);
  double total = 0.0;
  for (const MeanStat& b : s.backups) total += b.mean;
  for (const MeanStat& b : s.backups) s.backup_share.push_back(total > 0.0 ? b.mean / total : 0.0);
  s.time_s = SummariseValues(times, confidence);
  s.time_ended_s = SummariseValues(times_ended, confidence);
  if (!st.trials.empty()) {
    for (std::size_t k = 0; k < st.trials.front().attacker_counters.size(); ++k) {
      std::vector<double> values;
      for (const MatchTrialResult& t : st.trials) values.push_back(t.attacker_counters[k].value);
      s.team_counters.emplace_back(st.trials.front().attacker_counters[k].name,
                                   SummariseValues(values, confidence));
    }
  }
  return s;
}

}  // namespace

std::vector<ScenarioSummary> SummarisePassing(const PassingResult& result, double confidence) {
  std::vector<ScenarioSummary> summaries;
  for (const ScenarioTrials& st : result.scenarios) summaries.push_back(Summarise(st, confidence));
  return summaries;
}

}  // namespace foresight
