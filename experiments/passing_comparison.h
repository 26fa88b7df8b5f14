// Two teams played from the same trial keys (experiments/passing.h: common random numbers), so
// trial i of one team and trial i of the other met the same random draws as far as their play
// allowed: the comparison is paired. Per scenario and measure, the difference d_i = first_i -
// second_i (an outcome as 0/1, the opponents' touches, the trial time) with its mean and t
// interval (Student, n - 1 degrees of freedom: for 0/1 outcomes the usual large-sample interval
// of a paired difference of proportions). The paper reports no intervals (Ros et al. 2009,
// sec. 5.2 only names a t-test for Table 5).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/passing_stats.h"

namespace foresight {

struct PairedRow {
  std::string measure;  // "to_goal", "goal", ..., "touches_D", "time_s"
  double first_mean = 0.0;
  double second_mean = 0.0;
  MeanStat difference;  // first - second
};

struct ScenarioComparison {
  int scenario = 0;
  std::string name;
  std::vector<PairedRow> rows;
};

struct PassingComparison {
  std::string first, second;  // team names
  std::vector<ScenarioComparison> scenarios;
};

// The paired difference first_i - second_i of `value` over the trials of one scenario; with
// `skip_timeouts` only the pairs in which neither trial timed out (the paper's Table 5 leaves
// timeouts out). Precondition: both hold the same number of trials.
MeanStat PairTrials(const ScenarioTrials& first, const ScenarioTrials& second,
                    const std::function<double(const MatchTrialResult&)>& value,
                    bool skip_timeouts, double confidence);

// Precondition: both results hold the same scenarios with the same number of trials.
PassingComparison ComparePassing(const std::string& first_team, const PassingResult& first,
                                 const std::string& second_team, const PassingResult& second,
                                 const std::vector<std::string>& opponent_names,
                                 double confidence);

nlohmann::ordered_json PassingComparisonJson(const PassingComparison& c);
std::string PassingComparisonText(const PassingComparison& c);

}  // namespace foresight
