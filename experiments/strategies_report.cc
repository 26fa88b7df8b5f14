#include "experiments/strategies_report.h"

#include "report/experiment_charts.h"
#include "report/experiment_maps.h"
#include "report/report_format.h"

namespace foresight {

namespace {

using Json = nlohmann::ordered_json;

Json IntervalJson(const Interval& i) {
  return Json::array({i.low, i.high});
}

Json ParamsJson(const StrategiesRun& run) {
  const StrategiesParams& p = *run.params;
  Json strategies = Json::array();
  for (Strategy s : p.strategies) strategies.push_back(StrategyName(s));
  Json j = InputsJson(run.provenance);
  j.update({{"strategies", strategies},
            {"starts", p.starts},
            {"max_steps", p.max_steps},
            {"samples_per_action", p.situation.evaluation.samples},
            {"walk_speed_mps", p.walk_speed_mps},
            {"turn_speed_deg_per_s", p.turn_speed_radps * kRadToDeg},
            {"turn_around_ball_speed_deg_per_s", p.turn_around_ball_speed_radps * kRadToDeg},
            {"example_start", p.example_start}});
  return j;
}

// Statistics over no runs are not 0: they are null.
Json OrNull(double value, bool defined) {
  return defined ? Json(value) : Json(nullptr);
}
Json OrNull(const Interval& i, bool defined) {
  return defined ? IntervalJson(i) : Json(nullptr);
}

Json SummaryJson(const StrategySummary& s) {
  const bool ended = s.ended > 0;
  Json j = {{"strategy", StrategyName(s.strategy)},
            {"runs", s.runs},
            {"ends",
             {{"goal", s.goals},
              {"own_goal", s.own_goals},
              {"out", s.outs},
              {"step_limit", s.step_limits},
              {"step_limit_stopped_at_contact", s.step_limits_at_contact}}},
            {"ended_runs", s.ended},
            {"kicks_missed", s.kick_status.missed},
            {"kicks_not_settled", s.kick_status.not_settled},
            {"kicks_fell", s.kick_status.fell},
            {"kicks_blocked", s.kick_status.blocked},
            {"goal_share", static_cast<double>(s.goals) / s.runs},
            {"goal_share_95", IntervalJson(s.goal_share_95)},
            {"kicks",
             {{"mean", OrNull(s.mean_kicks, ended)},
              {"mean_95", OrNull(s.mean_kicks_95, ended)},
              {"median", OrNull(s.median_kicks, ended)},
              {"max", s.max_kicks},
              {"histogram", s.kick_counts}}},
            {"time_s",
             {{"mean", OrNull(s.mean_time_s, ended)},
              {"mean_95", OrNull(s.mean_time_95, ended)},
              {"walk_mean", OrNull(s.mean_walk_s, ended)},
              {"turn_mean", OrNull(s.mean_turn_s, ended)},
              {"around_ball_mean", OrNull(s.mean_around_ball_s, ended)}}},
            {"turns_around_ball",
             {{"kicks", s.kicks_total},
              {"zero", s.turns_zero},
              {"max_deg", s.max_turn_deg},
              {"p95_deg", s.p95_turn_deg},
              {"above_90_deg", s.turns_above_90},
              {"above_100_deg", s.turns_above_100},
              {"bin_deg", kRotationBinDeg},
              {"histogram_nonzero", s.turn_bins}}}};
  if (s.paired_with_fast) {
    const bool paired = s.paired_runs > 0;
    j["minus_fast"] = {{"paired_runs", s.paired_runs},
                       {"kicks_mean", OrNull(s.kicks_minus_fast, paired)},
                       {"kicks_mean_95", OrNull(s.kicks_minus_fast_95, paired)},
                       {"time_mean_s", OrNull(s.time_minus_fast_s, paired)},
                       {"time_mean_95", OrNull(s.time_minus_fast_95, paired)}};
  }
  return j;
}

// The example run (Fig. 3) step by step, so a path can be replayed and inspected.
Json ExampleJson(const StrategyRuns& runs) {
  Json steps = Json::array();
  for (const StrategyStep& step : runs.example.steps_taken) {
    steps.push_back({{"robot",
                      {step.robot_at_ball.p_F.x(), step.robot_at_ball.p_F.y(),
                       step.robot_at_ball.theta_rad * kRadToDeg}},
                     {"ball", {step.p_F_ball.x(), step.p_F_ball.y()}},
                     {"kick", step.kick_index},
                     {"turn_deg", step.rotation_rad * kRadToDeg},
                     {"rest", {step.outcome.p_F_rest.x(), step.outcome.p_F_rest.y()}},
                     {"category", CategoryName(step.outcome.category)},
                     {"first_contact", ContactName(step.outcome.first_contact)}});
  }
  return {{"strategy", StrategyName(runs.strategy)},
          {"end", RunEndName(runs.example.end)},
          {"steps", steps}};
}

std::vector<double> BinEdges(int bins, double width, double first = 0.0) {
  std::vector<double> edges;
  for (int i = 0; i <= bins; ++i) edges.push_back(first + i * width);
  return edges;
}

}  // namespace

std::string StrategiesText(const StrategiesRun& run) {
  std::string text = Format("strategies: %d starts, kicks executed by %s\n", run.params->starts,
                            run.provenance.Input("executor").c_str());
  text +=
      "  strategy        goal    out  own goal  limit  kicks (mean)  time (s)  turn > 0  "
      "max turn\n";
  for (const StrategySummary& s : run.summaries) {
    const double n = s.runs;
    text += Format(
        "  %-13s  %5.1f%%  %5.1f%%  %5.1f%%  %5.1f%%  %12.2f  %8.1f  %7.1f%%  %6.1f deg\n",
        std::string(StrategyName(s.strategy)).c_str(), 100.0 * s.goals / n, 100.0 * s.outs / n,
        100.0 * s.own_goals / n, 100.0 * s.step_limits / n, s.mean_kicks, s.mean_time_s,
        s.kicks_total > 0 ? 100.0 * (s.kicks_total - s.turns_zero) / s.kicks_total : 0.0,
        s.max_turn_deg);
  }
  text += "  (kicks, time and turns over the runs that ended in a goal or out)\n";
  if (run.provenance.Input("executor") == "physics") {
    for (const StrategySummary& s : run.summaries) {
      text += Format("  physics kicks of %s: %s (still played as they happened)\n",
                     std::string(StrategyName(s.strategy)).c_str(),
                     StatusCountsText(s.kick_status).c_str());
    }
  }
  return text;
}

Json StrategiesJson(const StrategiesRun& run) {
  Json summaries = Json::array();
  for (const StrategySummary& s : run.summaries) summaries.push_back(SummaryJson(s));
  Json examples = Json::array();
  for (const StrategyRuns& runs : run.result.strategies) examples.push_back(ExampleJson(runs));
  const RunProvenance& p = run.provenance;
  return {{"experiment", "strategies"}, {"version", p.version},    {"seed", p.seed},
          {"params", ParamsJson(run)},  {"strategies", summaries}, {"example_runs", examples},
          {"run_time_s", p.run_time_s}};
}

std::string StrategiesRunsCsv(const StrategiesRun& run) {
  std::string csv =
      "start,strategy,end,kicks,steps,time_s,walk_s,turn_s,around_ball_s,"
      "turns_nonzero,max_turn_deg,start_robot_x_m,start_robot_y_m,"
      "start_robot_theta_deg,start_ball_x_m,start_ball_y_m,kicks_missed,kicks_not_settled,"
      "kicks_fell,kicks_blocked\n";
  for (const StrategyRuns& runs : run.result.strategies) {
    for (std::size_t i = 0; i < runs.runs.size(); ++i) {
      const StrategyRun& r = runs.runs[i];
      const StartPosition& start = run.result.starts[i];
      int nonzero = 0;
      double max_turn = 0.0;
      for (double rho : r.rotations_rad) {
        nonzero += rho != 0.0;
        max_turn = std::max(max_turn, std::abs(rho) * kRadToDeg);
      }
      csv += Format(
          "%zu,%s,%s,%d,%d,%.3f,%.3f,%.3f,%.3f,%d,%.2f,%.3f,%.3f,%.2f,%.3f,%.3f,%d,%d,%d,%d\n", i,
          std::string(StrategyName(runs.strategy)).c_str(), std::string(RunEndName(r.end)).c_str(),
          r.kicks, r.steps, r.TotalTime(), r.walk_s, r.turn_s, r.around_ball_s, nonzero, max_turn,
          start.robot.p_F.x(), start.robot.p_F.y(), start.robot.theta_rad * kRadToDeg,
          start.p_F_ball.x(), start.p_F_ball.y(), r.kick_status.missed, r.kick_status.not_settled,
          r.kick_status.fell, r.kick_status.blocked);
    }
  }
  return csv;
}

std::string StrategiesTurnsSvg(const StrategiesRun& run) {
  BinnedChart chart;
  chart.title = Format("Turns around the ball before a kick (%d starts; turns of 0 left out)",
                       run.params->starts);
  chart.x_label = "turn around the ball (deg)";
  chart.y_label = "kicks";
  chart.log_y = true;
  chart.bin_edges = BinEdges(kRotationBins, kRotationBinDeg);
  for (const StrategySummary& s : run.summaries) {
    chart.series.push_back({std::string(StrategyName(s.strategy)), s.turn_bins});
  }
  return BinnedChartSvg(chart);
}

std::string StrategiesKicksSvg(const StrategiesRun& run) {
  // Long tails (a few runs of 50+ kicks) would squeeze the bars: the last bin gathers them.
  constexpr int kLastBin = 25;
  int max_kicks = 1;
  for (const StrategySummary& s : run.summaries) max_kicks = std::max(max_kicks, s.max_kicks);
  const int last = std::min(max_kicks, kLastBin);
  BinnedChart chart;
  chart.title = Format("Kicks until goal or out (%d starts)", run.params->starts);
  if (max_kicks > last) chart.title += Format("; the last bar: %d or more", last);
  chart.x_label = "kicks";
  chart.y_label = "runs";
  chart.bin_edges = BinEdges(last + 1, 1.0, -0.5);
  for (const StrategySummary& s : run.summaries) {
    std::vector<double> counts(static_cast<std::size_t>(last) + 1, 0.0);
    for (std::size_t k = 0; k < s.kick_counts.size(); ++k) {
      counts[std::min(k, static_cast<std::size_t>(last))] += s.kick_counts[k];
    }
    chart.series.push_back({std::string(StrategyName(s.strategy)), counts});
  }
  return BinnedChartSvg(chart);
}

std::string StrategiesPathsSvg(const StrategiesRun& run) {
  BallPathsMap map;
  const int start = run.params->example_start;
  map.title = Format("Ball paths from start %d, one per strategy", start);
  map.robot_start = run.result.starts[static_cast<std::size_t>(start)].robot;
  for (const StrategyRuns& runs : run.result.strategies) {
    BallPath path;
    path.balls_F.push_back(run.result.starts[static_cast<std::size_t>(start)].p_F_ball);
    for (const StrategyStep& step : runs.example.steps_taken) {
      if (step.kick_index != kNoKick) path.balls_F.push_back(step.outcome.p_F_rest);
    }
    path.name = Format("%s: %d kicks, %s", std::string(StrategyName(runs.strategy)).c_str(),
                       runs.example.kicks, std::string(RunEndName(runs.example.end)).c_str());
    map.paths.push_back(std::move(path));
  }
  return BallPathsSvg(run.params->situation.field, map);
}

}  // namespace foresight
