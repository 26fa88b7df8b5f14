// The pooled rolling deceleration of deceleration_fit.h.
//
// Formulas, for each usable trial i with samples (t_ij, v_ij), j = 1..n_i:
//   tbar_i, vbar_i the trial means, Sxx_i = sum_j (t_ij - tbar_i)^2,
//   Sxy_i = sum_j (t_ij - tbar_i)(v_ij - vbar_i);
//   a = -sum_i Sxy_i / sum_i Sxx_i, the least-squares common slope with one intercept per trial
//     (the "within" estimator, e.g. Wooldridge, Econometric Analysis of Cross Section and Panel
//     Data, 2nd ed., 2010, section 10.5);
//   residual sd = sqrt(sum_ij e_ij^2 / (N - k - 1)), e_ij = v_ij - vbar_i + a (t_ij - tbar_i), for
//     N points, k intercepts and one slope;
//   interval: cluster bootstrap resampling whole trials with replacement (Davison & Hinkley,
//     Bootstrap Methods and their Application, 1997, section 3.8), a*_r = -sum Sxy / sum Sxx over
//     the drawn trials, percentile interval [q((1-c)/2), q((1+c)/2)] with linear interpolation
//     between order statistics (Efron & Tibshirani 1993, ch. 13; Hyndman & Fan 1996, type 7).
//     Resample r draws from RandomStream(StreamKey(seed, r, kBootstrapDomain)) only.
// A trial is usable with at least 3 samples whose times are not all equal (Sxx_i > 0), so every
// resample has a positive denominator.
#include "validation/deceleration_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/random.h"

namespace foresight {
namespace {

[[noreturn]] void Fail(const std::string& what) {
  throw std::invalid_argument("FitDeceleration: " + what);
}

struct TrialSums {
  const std::vector<SpeedSample>* samples;
  double t_mean;
  double v_mean;
  double sxx;
  double sxy;
};

TrialSums SumTrial(const std::vector<SpeedSample>& trial) {
  const double n = static_cast<double>(trial.size());
  TrialSums s{&trial, 0.0, 0.0, 0.0, 0.0};
  for (const SpeedSample& p : trial) {
    s.t_mean += p.t_s / n;
    s.v_mean += p.speed_mps / n;
  }
  for (const SpeedSample& p : trial) {
    s.sxx += (p.t_s - s.t_mean) * (p.t_s - s.t_mean);
    s.sxy += (p.t_s - s.t_mean) * (p.speed_mps - s.v_mean);
  }
  return s;
}

void CheckInputs(std::span<const std::vector<SpeedSample>> per_trial, double confidence,
                 int resamples) {
  if (!(confidence > 0.0 && confidence < 1.0)) {
    Fail("confidence must be in (0, 1), got " + std::to_string(confidence));
  }
  if (resamples < 2) Fail("need at least 2 resamples, got " + std::to_string(resamples));
  for (std::size_t i = 0; i < per_trial.size(); ++i) {
    for (const SpeedSample& p : per_trial[i]) {
      if (!std::isfinite(p.t_s) || !std::isfinite(p.speed_mps)) {
        Fail("non-finite sample in trial " + std::to_string(i));
      }
    }
  }
}

double ResidualSd(const std::vector<TrialSums>& trials, double deceleration, int samples) {
  double sse = 0.0;
  for (const TrialSums& s : trials) {
    for (const SpeedSample& p : *s.samples) {
      const double e = p.speed_mps - s.v_mean + deceleration * (p.t_s - s.t_mean);
      sse += e * e;
    }
  }
  const int dof = samples - static_cast<int>(trials.size()) - 1;  // >= 3: k >= 2, N >= 3k
  return std::sqrt(sse / dof);
}

Interval ClusterBootstrap(const std::vector<TrialSums>& trials, double confidence, int resamples,
                          std::uint64_t seed) {
  const std::size_t k = trials.size();
  std::vector<double> estimates(resamples);
  for (int r = 0; r < resamples; ++r) {
    RandomStream stream(StreamKey(seed, static_cast<std::uint64_t>(r), kBootstrapDomain));
    double sxx = 0.0, sxy = 0.0;
    for (std::size_t j = 0; j < k; ++j) {
      const std::size_t i =
          std::min(k - 1, static_cast<std::size_t>(stream.NextUniform() * static_cast<double>(k)));
      sxx += trials[i].sxx;
      sxy += trials[i].sxy;
    }
    estimates[r] = -sxy / sxx;
  }
  return PercentileInterval(std::move(estimates), confidence);
}

}  // namespace

DecelerationFit FitDeceleration(std::span<const std::vector<SpeedSample>> per_trial,
                                double confidence, int resamples, std::uint64_t seed) {
  CheckInputs(per_trial, confidence, resamples);
  std::vector<TrialSums> trials;
  DecelerationFit fit;
  double sxx = 0.0, sxy = 0.0;
  for (const std::vector<SpeedSample>& trial : per_trial) {
    if (trial.size() < 3) continue;
    const TrialSums s = SumTrial(trial);
    if (!(s.sxx > 0.0)) continue;  // all samples at one time: no slope information
    trials.push_back(s);
    fit.samples += static_cast<int>(trial.size());
    sxx += s.sxx;
    sxy += s.sxy;
  }
  if (trials.size() < 2) {
    Fail("need at least 2 trials with 3 or more samples spanning time, got " +
         std::to_string(trials.size()));
  }
  fit.trials = static_cast<int>(trials.size());
  fit.deceleration_mps2 = -sxy / sxx;
  fit.residual_sd_mps = ResidualSd(trials, fit.deceleration_mps2, fit.samples);
  fit.ci_mps2 = ClusterBootstrap(trials, confidence, resamples, seed);
  return fit;
}

}  // namespace foresight
