#include "experiments/strategy_stats.h"

#include <algorithm>
#include <cmath>

namespace foresight {

namespace {

constexpr double kConfidence = 0.95;

double Mean(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v;
  return x.empty() ? 0.0 : sum / static_cast<double>(x.size());
}

double Median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  std::ranges::sort(x);
  const std::size_t n = x.size();
  return n % 2 == 1 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

Interval MeanInterval(const std::vector<double>& x) {
  if (x.size() < 2) return {Mean(x), Mean(x)};
  return MeanTInterval(x, kConfidence);
}

void CountEnds(const StrategyRuns& runs, StrategySummary& s) {
  for (const StrategyRun& run : runs.runs) {
    s.goals += run.end == RunEnd::kGoal;
    s.own_goals += run.end == RunEnd::kOwnGoal;
    s.outs += run.end == RunEnd::kOut;
    s.step_limits += run.end == RunEnd::kStepLimit;
    s.step_limits_at_contact += run.end == RunEnd::kStepLimit && run.last_contact != Contact::kNone;
    s.kick_status.Add(run.kick_status);
  }
  s.ended = s.runs - s.step_limits;
  s.goal_share_95 = WilsonInterval(s.goals, s.runs, kConfidence);
}

void SummariseKicksAndTime(const StrategyRuns& runs, StrategySummary& s) {
  std::vector<double> kicks, time;
  for (const StrategyRun& run : runs.runs) {
    if (run.end == RunEnd::kStepLimit) continue;
    kicks.push_back(run.kicks);
    time.push_back(run.TotalTime());
    s.mean_walk_s += run.walk_s / s.ended;
    s.mean_turn_s += run.turn_s / s.ended;
    s.mean_around_ball_s += run.around_ball_s / s.ended;
    s.max_kicks = std::max(s.max_kicks, run.kicks);
  }
  s.mean_kicks = Mean(kicks);
  s.mean_kicks_95 = MeanInterval(kicks);
  s.median_kicks = Median(kicks);
  s.mean_time_s = Mean(time);
  s.mean_time_95 = MeanInterval(time);
  s.kick_counts.assign(static_cast<std::size_t>(s.max_kicks) + 1, 0.0);
  for (double k : kicks) s.kick_counts[static_cast<std::size_t>(k)] += 1;
}

void SummariseTurns(const StrategyRuns& runs, StrategySummary& s) {
  s.turn_bins.assign(kRotationBins, 0.0);
  std::vector<double> turns_deg;
  for (const StrategyRun& run : runs.runs) {
    if (run.end == RunEnd::kStepLimit) continue;
    for (double rho : run.rotations_rad) {
      ++s.kicks_total;
      const double deg = std::abs(rho) * kRadToDeg;
      if (deg == 0.0) {
        ++s.turns_zero;
        continue;
      }
      turns_deg.push_back(deg);
      s.max_turn_deg = std::max(s.max_turn_deg, deg);
      s.turns_above_90 += deg > 90.0;
      s.turns_above_100 += deg > 100.0;
      const int bin = std::min(kRotationBins - 1, static_cast<int>(deg / kRotationBinDeg));
      s.turn_bins[static_cast<std::size_t>(bin)] += 1;
    }
  }
  if (!turns_deg.empty()) s.p95_turn_deg = PercentileInterval(turns_deg, 0.90).high;
}

void PairWithFast(const StrategyRuns& fast, const StrategyRuns& runs, StrategySummary& s) {
  std::vector<double> kicks, time;
  for (std::size_t i = 0; i < runs.runs.size(); ++i) {
    if (runs.runs[i].end == RunEnd::kStepLimit || fast.runs[i].end == RunEnd::kStepLimit) continue;
    kicks.push_back(runs.runs[i].kicks - fast.runs[i].kicks);
    time.push_back(runs.runs[i].TotalTime() - fast.runs[i].TotalTime());
  }
  s.paired_with_fast = true;
  s.paired_runs = static_cast<int>(kicks.size());
  s.kicks_minus_fast = Mean(kicks);
  s.kicks_minus_fast_95 = MeanInterval(kicks);
  s.time_minus_fast_s = Mean(time);
  s.time_minus_fast_95 = MeanInterval(time);
}

}  // namespace

std::vector<StrategySummary> SummariseStrategies(const StrategiesResult& result) {
  const StrategyRuns* fast = nullptr;
  for (const StrategyRuns& runs : result.strategies) {
    if (runs.strategy == Strategy::kFast) fast = &runs;
  }
  std::vector<StrategySummary> summaries;
  for (const StrategyRuns& runs : result.strategies) {
    StrategySummary s;
    s.strategy = runs.strategy;
    s.runs = static_cast<int>(runs.runs.size());
    if (s.runs == 0) continue;
    CountEnds(runs, s);
    SummariseKicksAndTime(runs, s);
    SummariseTurns(runs, s);
    if (fast != nullptr && fast != &runs) PairWithFast(*fast, runs, s);
    summaries.push_back(std::move(s));
  }
  return summaries;
}

}  // namespace foresight
