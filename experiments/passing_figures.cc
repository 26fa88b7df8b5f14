#include "experiments/passing_figures.h"

#include "report/chart_axes.h"
#include "report/charts.h"
#include "report/field_svg.h"
#include "report/report_format.h"

namespace foresight {

namespace {

std::string PercentLabel(const std::string& what, const std::string& scenario, int count, int n,
                         const Interval& ci) {
  return Format("%s, %s: %d of %d (%.1f %%, interval %.1f-%.1f %%)", scenario.c_str(), what.c_str(),
                count, n, 100.0 * count / n, 100.0 * ci.low, 100.0 * ci.high);
}

// One outcome's share in one scenario as a point with its interval: `to_goal` (the paper's "to
// goal") or outcome `o`.
ScatterPoint SharePoint(const ScenarioSummary& s, bool to_goal, TrialOutcome o, double x,
                        int series, const std::string& what) {
  const int count = to_goal ? s.to_goal : s.counts[static_cast<std::size_t>(o)];
  const Interval ci = to_goal ? s.to_goal_ci : s.shares_ci[static_cast<std::size_t>(o)];
  ScatterPoint p;
  p.x = x;
  p.y = 100.0 * count / s.trials;
  p.y_low = 100.0 * ci.low;
  p.y_high = 100.0 * ci.high;
  p.series = series;
  p.label = PercentLabel(what, s.name, count, s.trials, ci);
  return p;
}

std::vector<TrialOutcome> ShownOutcomes(const PassingRun& run) {
  // Classes no trial of this configuration can end with are left out (no goalie: no goal,
  // close or block in 2D; no penalty-area rule in DG).
  std::vector<TrialOutcome> shown;
  for (int k = 0; k < kTrialOutcomeCount; ++k) {
    const auto outcome = static_cast<TrialOutcome>(k);
    const bool has_goalie = [&] {
      for (const OpponentSpec& o : run.setup->config.opponents) {
        if (o.role == OpponentRole::kGoalie) return true;
      }
      return false;
    }();
    if (outcome == TrialOutcome::kBlock && !has_goalie) continue;
    if (outcome == TrialOutcome::kPenaltyArea && !run.setup->config.penalty_area_ends_trial) {
      continue;
    }
    if ((outcome == TrialOutcome::kGoal || outcome == TrialOutcome::kClose) &&
        run.setup->config.penalty_area_ends_trial) {
      continue;
    }
    shown.push_back(outcome);
  }
  return shown;
}

std::string RunTitle(const PassingRun& run, const std::string& what) {
  return what + " (" + run.team + " vs " + run.setup->config.name + ", " +
         std::to_string(run.setup->trials) + " trials per scenario)";
}

}  // namespace

std::string PassingOutcomesSvg(const PassingRun& run) {
  ScatterChart chart;
  chart.title = RunTitle(run, "Outcome shares");
  chart.x_label = "scenario";
  chart.y_label = "share of trials (%)";
  chart.identity_line = false;
  chart.size = {720.0, 420.0};
  const std::vector<TrialOutcome> shown = ShownOutcomes(run);
  const double width = 0.7 / static_cast<double>(shown.size() + 1);
  for (const ScenarioSummary& s : run.summaries) {
    for (std::size_t k = 0; k < shown.size() + 1; ++k) {
      const bool to_goal = k == shown.size();
      const TrialOutcome o = to_goal ? TrialOutcome::kGoal : shown[k];
      const std::string name = to_goal ? "to goal" : std::string(TrialOutcomeName(o));
      chart.points.push_back(SharePoint(s, to_goal, o,
                                        s.scenario - 0.35 + width * (static_cast<double>(k) + 0.5),
                                        static_cast<int>(k), name));
    }
  }
  for (TrialOutcome o : shown) chart.series_names.emplace_back(TrialOutcomeName(o));
  chart.series_names.emplace_back("to goal");
  return ScatterSvg(chart);
}

std::string PassingPossessionSvg(const PassingRun& run) {
  ScatterChart chart;
  chart.title = RunTitle(run, "Opponents' possession (touches per trial)");
  chart.x_label = "scenario";
  chart.y_label = "touches per trial";
  chart.identity_line = false;
  chart.size = {720.0, 420.0};
  const auto& opponents = run.setup->config.opponents;
  for (const ScenarioSummary& s : run.summaries) {
    for (std::size_t o = 0; o < s.possession.size(); ++o) {
      const MeanStat& m = s.possession[o];
      ScatterPoint p{s.scenario - 0.1 + 0.2 * static_cast<double>(o),
                     m.mean,
                     m.ci.low,
                     m.ci.high,
                     "",
                     static_cast<int>(o)};
      p.label = Format("%s, %s: %.2f touches (sd %.2f, n %d)", s.name.c_str(),
                       opponents[o].name.c_str(), m.mean, m.sd, m.n);
      chart.points.push_back(p);
    }
  }
  for (const OpponentSpec& o : opponents) chart.series_names.push_back(o.name);
  return ScatterSvg(chart);
}

std::string PassingTimeSvg(const PassingRun& run) {
  ScatterChart chart;
  chart.title = RunTitle(run, "Trial time (mean and interval)");
  chart.x_label = "scenario";
  chart.y_label = "time (s)";
  chart.identity_line = false;
  chart.size = {720.0, 420.0};
  for (const ScenarioSummary& s : run.summaries) {
    const MeanStat* stats[2] = {&s.time_s, &s.time_ended_s};
    for (int k = 0; k < 2; ++k) {
      const MeanStat& m = *stats[k];
      if (m.n == 0) continue;
      ScatterPoint p{s.scenario - 0.1 + 0.2 * k, m.mean, m.ci.low, m.ci.high, "", k};
      p.label = Format("%s: %.2f s (sd %.2f, n %d)", s.name.c_str(), m.mean, m.sd, m.n);
      chart.points.push_back(p);
    }
  }
  chart.series_names = {"all trials", "without timeouts"};
  return ScatterSvg(chart);
}

std::string PassingTeamsSvg(const PassingRun& first, const PassingRun& second) {
  ScatterChart chart;
  chart.title = "Outcome shares, " + first.team + " and " + second.team + " from the same trials (" +
                first.setup->config.name + ", " + std::to_string(first.setup->trials) +
                " trials per scenario and team)";
  chart.x_label = "scenario";
  chart.y_label = "share of trials (%)";
  chart.identity_line = false;
  chart.size = {760.0, 440.0};
  std::vector<TrialOutcome> shown = {TrialOutcome::kOut};
  for (TrialOutcome o : ShownOutcomes(first)) {
    if (o == TrialOutcome::kBlock) shown.push_back(o);
  }
  const PassingRun* runs[2] = {&first, &second};
  const std::size_t series = 2 * (shown.size() + 1);
  const double width = 0.8 / static_cast<double>(series);
  for (std::size_t s = 0; s < first.summaries.size(); ++s) {
    std::size_t k = 0;
    for (std::size_t m = 0; m < shown.size() + 1; ++m) {
      for (const PassingRun* run : runs) {
        const ScenarioSummary& sum = run->summaries[s];
        const bool to_goal = m == 0;
        const TrialOutcome o = to_goal ? TrialOutcome::kGoal : shown[m - 1];
        const std::string what =
            run->team + " " + (to_goal ? "to goal" : std::string(TrialOutcomeName(o)));
        chart.points.push_back(SharePoint(sum, to_goal, o,
                                          sum.scenario - 0.4 + width * (static_cast<double>(k) + 0.5),
                                          static_cast<int>(k), what));
        if (s == 0) chart.series_names.push_back(what);
        ++k;
      }
    }
  }
  return ScatterSvg(chart);
}

}  // namespace foresight
