#include "experiments/stability_report.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "report/experiment_charts.h"
#include "report/experiment_maps.h"
#include "report/report_format.h"

namespace foresight {

namespace {

using Json = nlohmann::ordered_json;

int MapCountIndex(const StabilityRun& run) {
  const std::vector<int>& counts = run.params->sample_counts;
  for (std::size_t c = 0; c < counts.size(); ++c) {
    if (counts[c] == run.params->map_samples) return static_cast<int>(c);
  }
  return 0;  // Validate() guarantees map_samples is listed
}

Json ParamsJson(const StabilityRun& run) {
  const StabilityParams& p = *run.params;
  Json j = InputsJson(run.provenance);
  j.update({{"strategy", StrategyName(p.strategy)},
            {"samples_per_decision", p.sample_counts},
            {"grid_step_m", p.grid_step_m},
            {"heading_step_deg", p.heading_step_rad * kRadToDeg},
            {"repeats", p.repeats},
            {"map_samples", p.map_samples},
            {"rotation_bin_deg", p.rotation_bin_rad * kRadToDeg}});
  return j;
}

// naoth never turns: with k kicks it chooses among k + 1 decisions, so its most likely one has
// at least 1 / (k + 1) of the votes. With k <= 3 the "<= 20 %" share is 0 by construction.
std::string ConstructionNote(const StabilityRun& run) {
  const int decisions = static_cast<int>(run.params->situation.kicks.kicks.size()) + 1;
  if (run.params->strategy != Strategy::kNaoth || decisions > 4) return "";
  return Format(
      "naoth chooses among %d decisions without a turn, so the most likely one always "
      "has at least %d%%: the <= 20%% share is 0 by construction (the paper's figure "
      "needs the decision with the turn: --params stability_parametric)",
      decisions, 100 / decisions);
}

}  // namespace

double WorstUncertainShareFrom(const StabilityResult& result, int min_samples) {
  double worst = std::numeric_limits<double>::quiet_NaN();
  for (const StabilityCount& c : result.counts) {
    if (c.samples >= min_samples && !(c.share_at_most_20 <= worst)) worst = c.share_at_most_20;
  }
  return worst;
}

std::string StabilityText(const StabilityRun& run) {
  const StabilityResult& r = run.result;
  std::string text = Format(
      "stability: %d poses (%zu positions x %zu headings), %d decisions "
      "each per sample count, strategy %s\n",
      r.grid.PoseCount(), r.grid.positions_F.size(), r.grid.headings_rad.size(),
      run.params->repeats, std::string(StrategyName(run.params->strategy)).c_str());
  text += "  samples   >80%    >50%   <=20%   mean top share\n";
  for (const StabilityCount& c : r.counts) {
    text += Format("  %7d  %5.1f%%  %5.1f%%  %5.1f%%   %.3f\n", c.samples, 100.0 * c.share_above_80,
                   100.0 * c.share_above_50, 100.0 * c.share_at_most_20, c.mean_top_share);
  }
  const std::string note = ConstructionNote(run);
  const double worst = WorstUncertainShareFrom(r, 20);
  if (!note.empty()) {
    text += note + "\n";
  } else if (std::isfinite(worst)) {
    text += Format(
        "from 20 samples on, at most %.1f%% of poses have a most likely decision of "
        "<= 20%% (paper: about 10%%)\n",
        100.0 * worst);
  }
  return text;
}

Json StabilityJson(const StabilityRun& run) {
  const StabilityResult& r = run.result;
  Json counts = Json::array();
  for (const StabilityCount& c : r.counts) {
    counts.push_back({{"samples", c.samples},
                      {"share_above_80", c.share_above_80},
                      {"share_above_50", c.share_above_50},
                      {"share_at_most_20", c.share_at_most_20},
                      {"mean_top_share", c.mean_top_share},
                      {"mean_distinct_decisions", c.mean_distinct}});
  }
  const double worst = WorstUncertainShareFrom(r, 20);
  Json j = {{"experiment", "stability"},
            {"version", run.provenance.version},
            {"seed", run.provenance.seed},
            {"params", ParamsJson(run)},
            {"grid",
             {{"positions", r.grid.positions_F.size()},
              {"headings", r.grid.headings_rad.size()},
              {"poses", r.grid.PoseCount()}}},
            {"decisions", r.decisions},
            {"counts", counts}};
  j["max_share_at_most_20_from_20_samples"] = std::isfinite(worst) ? Json(worst) : Json(nullptr);
  const std::string note = ConstructionNote(run);
  if (!note.empty()) j["note"] = note;
  j["run_time_s"] = run.provenance.run_time_s;
  return j;
}

std::string StabilityCountsCsv(const StabilityRun& run) {
  std::string csv =
      "samples,share_above_80,share_above_50,share_at_most_20,mean_top_share,"
      "mean_distinct_decisions\n";
  for (const StabilityCount& c : run.result.counts) {
    csv += Format("%d,%.6f,%.6f,%.6f,%.6f,%.4f\n", c.samples, c.share_above_80, c.share_above_50,
                  c.share_at_most_20, c.mean_top_share, c.mean_distinct);
  }
  return csv;
}

std::string StabilityPositionsCsv(const StabilityRun& run) {
  const StabilityResult& r = run.result;
  std::string csv = "x_m,y_m";
  std::vector<std::vector<double>> means;
  for (std::size_t c = 0; c < r.counts.size(); ++c) {
    csv += Format(",mean_top_share_n%d", r.counts[c].samples);
    means.push_back(r.PositionMeans(static_cast<int>(c)));
  }
  csv += "\n";
  for (std::size_t p = 0; p < r.grid.positions_F.size(); ++p) {
    csv += Format("%.3f,%.3f", r.grid.positions_F[p].x(), r.grid.positions_F[p].y());
    for (const std::vector<double>& m : means) csv += Format(",%.4f", m[p]);
    csv += "\n";
  }
  return csv;
}

std::string StabilityPlotSvg(const StabilityRun& run) {
  LineChart chart;
  chart.title = "Decision stability (" + std::string(StrategyName(run.params->strategy)) + ", " +
                std::to_string(run.params->repeats) + " decisions per pose)";
  chart.x_label = "samples per action N";
  chart.y_label = "share of poses";
  chart.log_x = chart.log_y = true;
  LineSeries above_80{"most likely decision > 80 %", {}, {}};
  LineSeries above_50{"most likely decision > 50 %", {}, {}};
  LineSeries at_most_20{"most likely decision <= 20 %", {}, {}};
  for (const StabilityCount& c : run.result.counts) {
    for (LineSeries* s : {&above_80, &above_50, &at_most_20}) s->x.push_back(c.samples);
    above_80.y.push_back(c.share_above_80);
    above_50.y.push_back(c.share_above_50);
    at_most_20.y.push_back(c.share_at_most_20);
  }
  // A share of 0 cannot be drawn on the log axis; say so rather than leave the legend unexplained
  // (with at most 4 possible decisions, e.g. naoth's, the top share is never below 25 %).
  for (LineSeries* s : {&above_80, &above_50, &at_most_20}) {
    if (std::ranges::all_of(s->y, [](double y) { return y <= 0.0; })) s->name += ": 0 at every N";
  }
  chart.series = {above_80, above_50, at_most_20};
  chart.x_markers = {static_cast<double>(run.params->map_samples)};
  chart.x_markers_label = "N = " + std::to_string(run.params->map_samples);
  return LineChartSvg(chart);
}

std::string StabilityMapSvg(const StabilityRun& run) {
  const StabilityResult& r = run.result;
  FieldCellMap map;
  map.title = Format("Share of the most likely decision, N = %d, mean over %zu headings",
                     run.params->map_samples, r.grid.headings_rad.size());
  map.value_label = "share of the most likely decision";
  map.cell_size_m = r.grid.cell_size_m;
  map.cell_centres_F = r.grid.positions_F;
  map.values = r.PositionMeans(MapCountIndex(run));
  // The scale starts at the lowest value's tenth, so the differences between cells stay visible.
  double lowest = 1.0;
  for (double v : map.values) lowest = std::min(lowest, v);
  map.value_lo = std::clamp(std::floor(lowest * 10.0) / 10.0, 0.0, 0.9);
  map.value_hi = 1.0;
  return FieldCellMapSvg(run.params->situation.field, map);
}

}  // namespace foresight
