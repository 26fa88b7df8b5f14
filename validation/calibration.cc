#include "validation/calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "common/geometry.h"
#include "common/random.h"

namespace foresight {

namespace {

constexpr int kMinObservations = 8;
constexpr double kOnCarpetTolerance_m = 1e-3;

// d = b w with w = v0^2 / 2 and b = 1 / a; b by least squares through the origin.
double DecelerationFromDistances(std::span<const double> w, std::span<const double> d) {
  double wd = 0.0, ww = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    wd += w[i] * d[i];
    ww += w[i] * w[i];
  }
  return wd > 0.0 ? ww / wd : std::numeric_limits<double>::quiet_NaN();
}

DecelerationFit FitFromDistances(std::span<const KickObservation> kicks,
                                 const CalibrationSettings& settings) {
  std::vector<double> w, d;
  for (const KickObservation& k : kicks) {
    if (!k.has_roll_distance) continue;
    w.push_back(0.5 * k.launch_speed_mps * k.launch_speed_mps);
    d.push_back(k.roll_distance_m);
  }
  if (w.size() < 2) throw InputError("deceleration: fewer than 2 kicks with a roll distance");
  DecelerationFit fit;
  fit.trials = fit.samples = static_cast<int>(w.size());
  fit.deceleration_mps2 = DecelerationFromDistances(w, d);
  if (!std::isfinite(fit.deceleration_mps2)) {
    throw InputError("deceleration: the roll distances do not determine a deceleration");
  }
  double residual_sq = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double predicted_v = std::sqrt(2.0 * fit.deceleration_mps2 * d[i]);
    residual_sq += std::pow(predicted_v - std::sqrt(2.0 * w[i]), 2);
  }
  fit.residual_sd_mps = std::sqrt(residual_sq / std::max<std::size_t>(1, w.size() - 1));
  // Percentile bootstrap over kicks.
  std::vector<double> estimates;
  std::vector<double> bw(w.size()), bd(w.size());
  for (int r = 0; r < settings.resamples; ++r) {
    RandomStream stream(StreamKey(settings.seed, static_cast<std::uint64_t>(r), kBootstrapDomain));
    for (std::size_t i = 0; i < w.size(); ++i) {
      const auto j = static_cast<std::size_t>(stream.NextUniform() * static_cast<double>(w.size()));
      bw[i] = w[j];
      bd[i] = d[j];
    }
    const double a = DecelerationFromDistances(bw, bd);
    if (std::isfinite(a)) estimates.push_back(a);
  }
  fit.ci_mps2 = PercentileInterval(estimates, settings.confidence);
  return fit;
}

}  // namespace

KickCalibration CalibrateKick(const std::string& kick, std::span<const KickObservation> kicks,
                              const CalibrationSettings& settings) {
  if (static_cast<int>(kicks.size()) < kMinObservations) {
    throw InputError("kick '" + kick + "': " + std::to_string(kicks.size()) +
                     " observed kicks, at least " + std::to_string(kMinObservations) +
                     " are needed for a fit and its test");
  }
  KickCalibration c;
  c.kick = kick;
  c.observations = static_cast<int>(kicks.size());
  std::vector<double> speeds, directions;
  for (const KickObservation& k : kicks) {
    speeds.push_back(k.launch_speed_mps);
    directions.push_back(k.launch_direction_rad);
  }
  c.speed = FitNormal(speeds, settings.confidence);
  c.speed_normality = TestNormality(speeds);
  c.speed_qq = NormalQq(speeds, c.speed.mean, c.speed.sd);
  c.direction = FitCircular(directions, settings.confidence, settings.resamples, settings.seed);
  c.direction_unwrapped_rad = UnwrapAround(directions, c.direction.mean_rad);
  c.direction_normality = TestNormality(c.direction_unwrapped_rad);
  c.direction_qq = NormalQq(c.direction_unwrapped_rad, c.direction.mean_rad, c.direction.sd_rad);
  c.deceleration = FitPooledDeceleration(kicks, settings);
  return c;
}

std::optional<DecelerationFit> FitPooledDeceleration(std::span<const KickObservation> kicks,
                                                     const CalibrationSettings& settings) {
  std::vector<std::vector<SpeedSample>> rolling;
  int with_distance = 0;
  for (const KickObservation& k : kicks) {
    if (k.rolling.size() >= 3) rolling.push_back(k.rolling);
    with_distance += k.has_roll_distance;
  }
  if (rolling.size() >= 2) {
    return FitDeceleration(rolling, settings.confidence, settings.resamples, settings.seed);
  }
  if (with_distance >= 2) return FitFromDistances(kicks, settings);
  return std::nullopt;
}

std::optional<LaunchOffsetFit> FitLaunchOffset(std::span<const KickObservation> kicks,
                                               double deceleration_mps2) {
  std::vector<double> residuals;
  LaunchOffsetFit fit;
  for (const KickObservation& k : kicks) {
    if (!k.has_launch_offset || !k.has_roll_distance) continue;
    const double rest_distance_m = k.launch_offset_m + k.roll_distance_m;
    residuals.push_back(rest_distance_m -
                        k.launch_speed_mps * k.launch_speed_mps / (2.0 * deceleration_mps2));
    fit.launch_point_m += k.launch_offset_m;
    fit.rest_distance_m += rest_distance_m;
  }
  if (residuals.size() < 2) return std::nullopt;
  const double n = static_cast<double>(residuals.size());
  fit.kicks = static_cast<int>(residuals.size());
  fit.launch_point_m /= n;
  fit.rest_distance_m /= n;
  const MeanSd summary = SampleMeanSd(residuals);
  fit.unclamped_offset_m = summary.mean;
  fit.standard_error_m = summary.sd / std::sqrt(n);
  fit.offset_m = std::max(0.0, fit.unclamped_offset_m);
  return fit;
}

KickObservation ObservationOf(const TrialResult& trial, double ball_radius_m,
                              double min_speed_mps) {
  KickObservation k;
  k.launch_speed_mps = trial.launch_speed_mps;
  k.launch_direction_rad = trial.launch_direction_rad;
  if (!trial.launched || trial.outcome.first_contact != Contact::kNone) return k;
  k.roll_distance_m = (trial.outcome.p_F_rest - trial.p_F_launch).norm();
  k.has_roll_distance = trial.settled;
  const double t_launch = trial.t_first_touch_s + trial.t_launch_s;
  for (const TracePoint& p : trial.trace) {
    if (p.t_s < t_launch - 1e-9) continue;
    const double speed = p.v_F.head<2>().norm();
    if (std::abs(p.p_F.z() - ball_radius_m) > kOnCarpetTolerance_m || speed < min_speed_mps) break;
    k.rolling.push_back({p.t_s, speed});
  }
  return k;
}

KickModel ApplyCalibration(const KickModel& base, std::span<const KickCalibration> calibrated,
                           const std::optional<DecelerationFit>& deceleration) {
  KickModel model = base;
  for (const KickCalibration& c : calibrated) {
    const std::optional<int> index = model.Find(c.kick);
    if (!index) throw InputError("kick '" + c.kick + "' is not in the base kick model");
    KickSpec& spec = model.kicks[*index];
    spec.speed_mps = c.speed.mean;
    spec.sigma_speed_mps = c.speed.sd;
    spec.direction_rad = WrapAngle(c.direction.mean_rad);
    spec.sigma_direction_rad = c.direction.sd_rad;
    if (c.launch_offset) spec.launch_offset_m = c.launch_offset->offset_m;
  }
  if (deceleration) model.rolling_deceleration_mps2 = deceleration->deceleration_mps2;
  return model;
}

}  // namespace foresight
