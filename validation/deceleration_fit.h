// The rolling deceleration from ball trajectories, by least squares.
//
// Model (docs/ARCHITECTURE.md, "OutcomeSimulator": the coarse model): a freely rolling ball's speed
// falls linearly, v_ij = v_i - a t_ij for sample j of trial i. Each trial has its own intercept v_i
// (its launch), all share the slope a, so the least-squares estimate is the pooled within-trial
// slope
//   a = - sum_ij (t_ij - tbar_i)(v_ij - vbar_i) / sum_ij (t_ij - tbar_i)^2.
// The carpet varies from trial to trial, so the points of one trial are not independent of each
// other; the interval is therefore a cluster bootstrap that resamples whole trials.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "stats/statistics.h"

namespace foresight {

struct SpeedSample {
  double t_s = 0.0;
  double speed_mps = 0.0;
};

struct DecelerationFit {
  int trials = 0;   // trials with at least 3 samples spanning time
  int samples = 0;  // points used
  double deceleration_mps2 = 0.0;
  Interval ci_mps2;              // cluster bootstrap over trials
  double residual_sd_mps = 0.0;  // of the pooled fit
};

// `per_trial`: the rolling samples of each trial (trials with fewer than 3 samples are skipped).
// Throws std::invalid_argument when fewer than 2 trials remain.
DecelerationFit FitDeceleration(std::span<const std::vector<SpeedSample>> per_trial,
                                double confidence, int resamples, std::uint64_t seed);

}  // namespace foresight
