// The passing experiment's tables (Ros et al. 2009, Tables 1, 2, 4 and 5) from its trials:
// per scenario the share of every outcome class and of "to goal" with Wilson intervals, the
// opponents' ball possession (touches: contact episodes, grabs included, which is when a kick
// can happen; the paper counts "touched or kicked"), the attackers' backing-ups and the trial
// time, each as mean, sd and a t interval, over all trials and over the trials that did not time
// out (Table 5 leaves timeouts out).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "experiments/passing.h"
#include "stats/statistics.h"

namespace foresight {

struct MeanStat {
  int n = 0;
  double mean = 0.0;
  double sd = 0.0;
  Interval ci;  // t interval of the mean; (mean, mean) when n < 2
};
MeanStat SummariseValues(const std::vector<double>& values, double confidence);

struct ScenarioSummary {
  int scenario = 0;
  std::string name;
  int trials = 0;
  std::array<int, kTrialOutcomeCount> counts{};
  std::array<Interval, kTrialOutcomeCount> shares_ci{};
  int to_goal = 0;
  Interval to_goal_ci;
  std::vector<MeanStat> possession;        // per opponent, all trials
  std::vector<MeanStat> possession_ended;  // per opponent, timeouts left out
  std::vector<MeanStat> opponent_kicks;    // per opponent, all trials
  std::vector<MeanStat> backups;           // per attacker, all trials
  std::vector<double> backup_share;        // per attacker: its share of the team's backing-ups
  int kicks_missed = 0;                    // over all trials (physics executors only)
  int kicks_not_settled = 0;
  int kicks_fell = 0;
  int kicks_blocked = 0;
  MeanStat time_s;
  MeanStat time_ended_s;
  // The attacking team's own counters (TeamPolicy::Counters, e.g. the CBR team's cases and
  // aborts), per trial, in the order the team reports them.
  std::vector<std::pair<std::string, MeanStat>> team_counters;
};

std::vector<ScenarioSummary> SummarisePassing(const PassingResult& result, double confidence);

}  // namespace foresight
