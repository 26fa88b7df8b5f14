#include "experiments/passing_comparison.h"

#include <cassert>
#include <functional>

#include "report/report_format.h"

namespace foresight {

namespace {

using Json = nlohmann::ordered_json;

PairedRow Pair(const std::string& name, const ScenarioTrials& a, const ScenarioTrials& b,
               const std::function<double(const MatchTrialResult&)>& value, double confidence) {
  PairedRow row;
  row.measure = name;
  double sa = 0.0, sb = 0.0;
  for (std::size_t i = 0; i < a.trials.size(); ++i) {
    sa += value(a.trials[i]);
    sb += value(b.trials[i]);
  }
  const double n = static_cast<double>(a.trials.size());
  row.first_mean = n > 0 ? sa / n : 0.0;
  row.second_mean = n > 0 ? sb / n : 0.0;
  row.difference = PairTrials(a, b, value, false, confidence);
  return row;
}

}  // namespace

MeanStat PairTrials(const ScenarioTrials& first, const ScenarioTrials& second,
                    const std::function<double(const MatchTrialResult&)>& value,
                    bool skip_timeouts, double confidence) {
  assert(first.trials.size() == second.trials.size());
  std::vector<double> d;
  for (std::size_t i = 0; i < first.trials.size(); ++i) {
    const MatchTrialResult& a = first.trials[i];
    const MatchTrialResult& b = second.trials[i];
    if (skip_timeouts &&
        (a.outcome == TrialOutcome::kTimeout || b.outcome == TrialOutcome::kTimeout)) {
      continue;
    }
    d.push_back(value(a) - value(b));
  }
  return SummariseValues(d, confidence);
}

PassingComparison ComparePassing(const std::string& first_team, const PassingResult& first,
                                 const std::string& second_team, const PassingResult& second,
                                 const std::vector<std::string>& opponent_names,
                                 double confidence) {
  assert(first.scenarios.size() == second.scenarios.size());
  PassingComparison c{first_team, second_team, {}};
  for (std::size_t s = 0; s < first.scenarios.size(); ++s) {
    const ScenarioTrials& a = first.scenarios[s];
    const ScenarioTrials& b = second.scenarios[s];
    assert(a.trials.size() == b.trials.size());
    ScenarioComparison sc{a.scenario, a.name, {}};
    sc.rows.push_back(Pair("to_goal", a, b,
                           [](const MatchTrialResult& t) { return IsToGoal(t.outcome) ? 1.0 : 0.0; },
                           confidence));
    for (int k = 0; k < kTrialOutcomeCount; ++k) {
      const auto outcome = static_cast<TrialOutcome>(k);
      sc.rows.push_back(Pair(std::string(TrialOutcomeName(outcome)), a, b,
                             [outcome](const MatchTrialResult& t) {
                               return t.outcome == outcome ? 1.0 : 0.0;
                             },
                             confidence));
    }
    for (std::size_t o = 0; o < opponent_names.size(); ++o) {
      sc.rows.push_back(Pair("touches_" + opponent_names[o], a, b,
                             [o](const MatchTrialResult& t) {
                               return static_cast<double>(t.counters.opponent_touches[o]);
                             },
                             confidence));
    }
    sc.rows.push_back(Pair("time_s", a, b,
                           [](const MatchTrialResult& t) { return t.counters.time_s; },
                           confidence));
    c.scenarios.push_back(std::move(sc));
  }
  return c;
}

Json PassingComparisonJson(const PassingComparison& c) {
  Json scenarios = Json::array();
  for (const ScenarioComparison& s : c.scenarios) {
    Json rows = Json::object();
    for (const PairedRow& r : s.rows) {
      rows[r.measure] = {{c.first, r.first_mean},
                         {c.second, r.second_mean},
                         {"difference", r.difference.mean},
                         {"difference_ci", Json::array({r.difference.ci.low, r.difference.ci.high})},
                         {"n", r.difference.n}};
    }
    scenarios.push_back({{"scenario", s.scenario}, {"name", s.name}, {"measures", rows}});
  }
  return {{"first", c.first}, {"second", c.second}, {"scenarios", scenarios}};
}

std::string PassingComparisonText(const PassingComparison& c) {
  std::string text = Format("paired differences %s - %s (mean, interval):\n", c.first.c_str(),
                            c.second.c_str());
  for (const ScenarioComparison& s : c.scenarios) {
    text += Format("%s:", s.name.c_str());
    for (const PairedRow& r : s.rows) {
      if (r.first_mean == 0.0 && r.second_mean == 0.0) continue;
      text += Format(" %s %+.3f [%+.3f, %+.3f];", r.measure.c_str(), r.difference.mean,
                     r.difference.ci.low, r.difference.ci.high);
    }
    text += "\n";
  }
  return text;
}

}  // namespace foresight
