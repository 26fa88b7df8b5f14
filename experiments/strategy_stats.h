// Summary statistics of the strategies experiment, per strategy: how runs ended (with Wilson
// intervals), kicks until goal or out, time, and the rotations around the ball (Fig. 5's
// histogram excludes turns of 0, as the paper's does). With `fast` among the strategies, every
// other strategy is also compared with it start by start (paired differences with t intervals).
//
// Kicks, time and turns are over the runs that ended in a goal or out (Fig. 5 counts kicks
// "until a goal was scored or it was out"). Runs stopped by the step limit are counted apart,
// with how many of them kept hitting a post, net or robot: with the fully inelastic contacts of
// the coarse model a ball resting against a post stops again at every kick towards it.
#pragma once

#include <vector>

#include "experiments/strategies.h"
#include "stats/statistics.h"

namespace foresight {

inline constexpr double kRotationBinDeg = 10.0;  // Fig. 5 (top): 0..180 deg in 10 deg bins
inline constexpr int kRotationBins = 18;

struct StrategySummary {
  Strategy strategy = Strategy::kFast;
  int runs = 0;
  int goals = 0, own_goals = 0, outs = 0, step_limits = 0;
  int step_limits_at_contact = 0;  // step-limit runs whose last kick stopped at a contact
  int ended = 0;                   // goals, own goals and outs: the runs the figures count
  Interval goal_share_95;

  double mean_kicks = 0.0;
  Interval mean_kicks_95;
  double median_kicks = 0.0;
  int max_kicks = 0;
  std::vector<double> kick_counts;  // [k]: runs that ended after k kicks, k = 0 .. max_kicks

  double mean_time_s = 0.0;
  Interval mean_time_95;
  double mean_walk_s = 0.0, mean_turn_s = 0.0, mean_around_ball_s = 0.0;

  int kicks_total = 0;
  StatusCounts kick_status;  // over all runs: kicks that missed the ball or did not settle
  int turns_zero = 0;        // kicks without a turn around the ball
  double max_turn_deg = 0.0;
  double p95_turn_deg = 0.0;  // of the kicks with a turn
  int turns_above_90 = 0, turns_above_100 = 0;
  std::vector<double> turn_bins;  // |turn| > 0 in kRotationBins bins of kRotationBinDeg

  bool paired_with_fast = false;  // the differences below are this minus fast, same starts
  int paired_runs = 0;            // starts where both ended
  double kicks_minus_fast = 0.0;
  Interval kicks_minus_fast_95;
  double time_minus_fast_s = 0.0;
  Interval time_minus_fast_95;
};

std::vector<StrategySummary> SummariseStrategies(const StrategiesResult& result);

}  // namespace foresight
