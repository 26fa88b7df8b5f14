#include "experiments/passing_ablations.h"

#include <algorithm>

#include "report/charts.h"
#include "report/report_format.h"

namespace foresight {

namespace {

using Json = nlohmann::ordered_json;

const PairedRow& Row(const PassingComparison& c, std::size_t scenario, const std::string& measure) {
  const auto& rows = c.scenarios[scenario].rows;
  return *std::find_if(rows.begin(), rows.end(),
                       [&](const PairedRow& r) { return r.measure == measure; });
}

double Share(const ScenarioSummary& s, TrialOutcome o) {
  return static_cast<double>(s.counts[static_cast<std::size_t>(o)]) / s.trials;
}

double CounterMean(const ScenarioSummary& s, const std::string& name) {
  for (const auto& [n, stat] : s.team_counters) {
    if (n == name) return stat.mean;
  }
  return 0.0;
}

Json Difference(const PairedRow& r) {
  return {{"mean", r.difference.mean}, {"ci", Json::array({r.difference.ci.low, r.difference.ci.high})}};
}

Json ScenarioJson(const AblationRun& run, std::size_t v, std::size_t s) {
  const ScenarioSummary& sum = run.summaries[v][s];
  const std::vector<std::string> opponents = run.base->config.OpponentNames();
  Json touches = Json::object();
  for (std::size_t o = 0; o < opponents.size(); ++o) {
    touches[opponents[o]] = {{"mean", sum.possession[o].mean},
                             {"ci", Json::array({sum.possession[o].ci.low, sum.possession[o].ci.high})}};
  }
  Json counters = Json::object();
  for (const auto& [name, stat] : sum.team_counters) counters[name] = stat.mean;
  Json vs_reference = Json::object(), vs_reactive = Json::object();
  for (const std::string measure : {"to_goal", "out", "time_s"}) {
    vs_reference[measure] = Difference(Row(run.vs_reference[v], s, measure));
    vs_reactive[measure] = Difference(Row(run.vs_reactive[v], s, measure));
  }
  return {{"scenario", sum.scenario},
          {"name", sum.name},
          {"to_goal", {{"share", static_cast<double>(sum.to_goal) / sum.trials},
                       {"ci", Json::array({sum.to_goal_ci.low, sum.to_goal_ci.high})}}},
          {"out", Share(sum, TrialOutcome::kOut)},
          {"block", Share(sum, TrialOutcome::kBlock)},
          {"timeout", Share(sum, TrialOutcome::kTimeout)},
          {"touches", touches},
          {"time_s", sum.time_s.mean},
          {"team_counters", counters},
          {"difference_vs_" + run.variants.front().name, vs_reference},
          {"difference_vs_reactive", vs_reactive}};
}

// The ablations read a trial's outcome and counters only: without its event log (hundreds of
// messages per CBR trial) and trace, 16 teams' trials fit in memory and in shard files.
void KeepCountsOnly(PassingResult& result) {
  for (ScenarioTrials& st : result.scenarios) {
    for (MatchTrialResult& t : st.trials) {
      t.events = {};
      t.trace = {};
    }
  }
}

}  // namespace

std::vector<std::string> AblationTeams(const std::vector<PassingVariant>& variants) {
  std::vector<std::string> teams = {"reactive"};
  for (const PassingVariant& v : variants) teams.push_back(v.name);
  return teams;
}

std::vector<PassingResult> PlayAblations(const PassingSetup& base,
                                         const std::vector<PassingVariant>& variants,
                                         const KickExecutor& executor, std::uint64_t seed,
                                         int threads,
                                         const std::function<void(int, int)>& progress,
                                         const Shard& shard) {
  const int per_team = base.trials * static_cast<int>(base.scenarios.size());
  const int teams = static_cast<int>(variants.size()) + 1;
  const int total = shard.OwnedCount(per_team * teams);
  int done_before = 0;
  const auto step = [&](int done, int) {
    if (progress) progress(done_before + done, total);
  };
  std::vector<PassingResult> results;
  for (int t = 0; t < teams; ++t) {
    const Shard mine = shard.From(t * per_team);
    if (t == 0) {
      results.push_back(RunPassing(base, "reactive", executor, seed, threads, step, mine));
    } else {
      const PassingSetup setup = variants[static_cast<std::size_t>(t - 1)].Apply(base);
      results.push_back(RunPassing(setup, "cbr", executor, seed, threads, step, mine));
    }
    KeepCountsOnly(results.back());
    done_before += mine.OwnedCount(per_team);
  }
  return results;
}

AblationRun SummariseAblations(const PassingSetup& base, std::vector<PassingVariant> variants,
                               const std::vector<PassingResult>& results) {
  AblationRun run;
  run.base = &base;
  run.variants = std::move(variants);
  const double confidence = base.params.confidence;
  const PassingResult& reactive = results.front();
  run.reactive = SummarisePassing(reactive, confidence);
  const std::vector<std::string> opponents = base.config.OpponentNames();
  const std::string& reference_name = run.variants.front().name;
  for (std::size_t v = 0; v < run.variants.size(); ++v) {
    const PassingResult& result = results[v + 1];
    run.summaries.push_back(SummarisePassing(result, confidence));
    run.vs_reference.push_back(ComparePassing(run.variants[v].name, result, reference_name,
                                              results[1], opponents, confidence));
    run.vs_reactive.push_back(ComparePassing(run.variants[v].name, result, "reactive", reactive,
                                             opponents, confidence));
  }
  return run;
}

Json AblationsJson(const AblationRun& run) {
  Json variants = Json::array();
  for (std::size_t v = 0; v < run.variants.size(); ++v) {
    Json scenarios = Json::array();
    for (std::size_t s = 0; s < run.summaries[v].size(); ++s) {
      scenarios.push_back(ScenarioJson(run, v, s));
    }
    variants.push_back({{"name", run.variants[v].name},
                        {"notes", run.variants[v].notes},
                        {"scenarios", scenarios}});
  }
  Json reactive = Json::array();
  for (const ScenarioSummary& s : run.reactive) {
    reactive.push_back({{"scenario", s.scenario},
                        {"to_goal", static_cast<double>(s.to_goal) / s.trials},
                        {"to_goal_ci", Json::array({s.to_goal_ci.low, s.to_goal_ci.high})},
                        {"out", Share(s, TrialOutcome::kOut)},
                        {"time_s", s.time_s.mean}});
  }
  Json inputs = InputsJson(run.provenance);
  inputs.update({{"trials_per_scenario", run.base->trials},
                 {"confidence", run.base->params.confidence}});
  return {{"experiment", "ablations"}, {"version", run.provenance.version},
          {"seed", run.provenance.seed}, {"params", inputs},
          {"reactive", reactive},        {"variants", variants},
          {"run_time_s", run.provenance.run_time_s}};
}

std::string AblationsCsv(const AblationRun& run) {
  const std::string ref = run.variants.front().name;
  std::string csv = "variant,scenario,to_goal,to_goal_low,to_goal_high,out,block,timeout,time_s,"
                    "cases_retrieved,cases_cooperative,d_to_goal_vs_" + ref + ",low,high,"
                    "d_to_goal_vs_reactive,low,high\n";
  for (std::size_t v = 0; v < run.variants.size(); ++v) {
    for (std::size_t s = 0; s < run.summaries[v].size(); ++s) {
      const ScenarioSummary& sum = run.summaries[v][s];
      const MeanStat& dr = Row(run.vs_reference[v], s, "to_goal").difference;
      const MeanStat& dx = Row(run.vs_reactive[v], s, "to_goal").difference;
      csv += Format("%s,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.2f,%.2f,%.2f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n",
                    run.variants[v].name.c_str(), sum.scenario,
                    static_cast<double>(sum.to_goal) / sum.trials, sum.to_goal_ci.low,
                    sum.to_goal_ci.high, Share(sum, TrialOutcome::kOut),
                    Share(sum, TrialOutcome::kBlock), Share(sum, TrialOutcome::kTimeout),
                    sum.time_s.mean, CounterMean(sum, "cases_retrieved"),
                    CounterMean(sum, "cases_cooperative"), dr.mean, dr.ci.low, dr.ci.high,
                    dx.mean, dx.ci.low, dx.ci.high);
    }
  }
  return csv;
}

std::string AblationsText(const AblationRun& run) {
  std::string text = Format("ablations: CBR team variants against %s, %d trials per scenario\n",
                            run.base->config.name.c_str(), run.base->trials);
  for (std::size_t s = 0; s < run.reactive.size(); ++s) {
    const ScenarioSummary& r = run.reactive[s];
    text += Format("%s: reactive to goal %.1f %%, block %.1f %%, out %.1f %%, timeout %.1f %%\n",
                   r.name.c_str(), 100.0 * r.to_goal / r.trials, 100.0 * Share(r, TrialOutcome::kBlock),
                   100.0 * Share(r, TrialOutcome::kOut), 100.0 * Share(r, TrialOutcome::kTimeout));
    for (std::size_t v = 0; v < run.variants.size(); ++v) {
      const ScenarioSummary& sum = run.summaries[v][s];
      const MeanStat& dr = Row(run.vs_reference[v], s, "to_goal").difference;
      text += Format("  %-24s to goal %5.1f %%  block %5.1f %%  out %5.1f %%  timeout %5.1f %%  "
                     "to goal vs %s %+5.1f [%+5.1f, %+5.1f]\n",
                     run.variants[v].name.c_str(), 100.0 * sum.to_goal / sum.trials,
                     100.0 * Share(sum, TrialOutcome::kBlock), 100.0 * Share(sum, TrialOutcome::kOut),
                     100.0 * Share(sum, TrialOutcome::kTimeout), run.variants.front().name.c_str(),
                     100.0 * dr.mean, 100.0 * dr.ci.low, 100.0 * dr.ci.high);
    }
  }
  return text;
}

std::string AblationsSvg(const AblationRun& run) {
  ScatterChart chart;
  chart.title = Format("To goal by variant (CBR against %s, %d trials per scenario; 0 = reactive)",
                       run.base->config.name.c_str(), run.base->trials);
  chart.x_label = "variant (0 reactive, 1 " + run.variants.front().name + ", ...)";
  chart.y_label = "to goal (% of trials)";
  chart.identity_line = false;
  chart.size = {900.0, 440.0};
  const double width = 0.6 / static_cast<double>(run.reactive.size());
  const auto add = [&](double x, const ScenarioSummary& s, std::size_t k, const std::string& who) {
    ScatterPoint p;
    p.x = x - 0.3 + width * (static_cast<double>(k) + 0.5);
    p.y = 100.0 * s.to_goal / s.trials;
    p.y_low = 100.0 * s.to_goal_ci.low;
    p.y_high = 100.0 * s.to_goal_ci.high;
    p.series = static_cast<int>(k);
    p.label = Format("%s, %s: %.1f %% to goal (%.1f-%.1f)", who.c_str(), s.name.c_str(), p.y,
                     p.y_low, p.y_high);
    chart.points.push_back(p);
  };
  for (std::size_t k = 0; k < run.reactive.size(); ++k) {
    add(0.0, run.reactive[k], k, "reactive");
    chart.series_names.push_back(run.reactive[k].name);
    for (std::size_t v = 0; v < run.variants.size(); ++v) {
      add(static_cast<double>(v + 1), run.summaries[v][k], k, run.variants[v].name);
    }
  }
  return ScatterSvg(chart);
}

}  // namespace foresight
