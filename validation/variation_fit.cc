#include "validation/variation_fit.h"

#include <algorithm>
#include <cmath>

#include "common/checks.h"
#include "common/error.h"
#include "common/geometry.h"
#include "stats/statistics.h"
#include "validation/physics_calibration.h"

namespace foresight {

namespace {

// Every kick of `observed` played in physics with `variation`, the same seeds every time.
std::map<std::string, LaunchSpread> Spreads(const VariationFitSettings& settings,
                                            const std::map<std::string, LaunchSpread>& observed,
                                            const TrialVariation& variation,
                                            const std::filesystem::path& models) {
  std::map<std::string, LaunchSpread> spreads;
  for (const auto& [kick, unused] : observed) {
    PhysicsCalibrationSettings s;
    s.robot = settings.robot;
    s.kick = kick;
    s.kick_field = "kick";
    s.trials = settings.trials;
    s.seed = settings.seed;
    s.threads = settings.threads;
    s.base = settings.base;
    s.variation = variation;
    s.progress = settings.progress;
    const PhysicsCalibration run = RunPhysicsCalibration(s, models);
    spreads[kick] = SpreadOf(run.kicks.front().observations);
  }
  return spreads;
}

// One equation per kick and quantity: u * a + w * b = y, weighted by 1 / y.
struct Equation {
  double a, b, y;
};

// min sum ((u a + w b - y) / y)^2 over u >= 0 and 0 <= w <= w_max (the 2 x 2 normal equations,
// or the best u with w at a bound, or w with u at 0).
std::pair<double, double> BoundedFit(const std::vector<Equation>& eqs, double w_max) {
  double aa = 0, ab = 0, bb = 0, ay = 0, by = 0;
  for (const Equation& e : eqs) {
    const double w = 1.0 / (e.y * e.y);
    aa += w * e.a * e.a, ab += w * e.a * e.b, bb += w * e.b * e.b;
    ay += w * e.a * e.y, by += w * e.b * e.y;
  }
  const double det = aa * bb - ab * ab;
  if (det > 1e-12 * aa * bb) {
    const double u = (ay * bb - by * ab) / det, w = (aa * by - ab * ay) / det;
    if (u >= 0.0 && w >= 0.0 && w <= w_max) return {u, w};
  }
  const auto cost = [&](double u, double w) {
    double c = 0.0;
    for (const Equation& e : eqs) c += std::pow((u * e.a + w * e.b - e.y) / e.y, 2);
    return c;
  };
  // The optimum lies on the boundary: w = 0, w = w_max (best u >= 0 for each) or u = 0.
  const auto best_u = [&](double w) {
    return aa > 0.0 ? std::max(0.0, (ay - w * ab) / aa) : 0.0;
  };
  const double w_alone = bb > 0.0 ? std::clamp(by / bb, 0.0, w_max) : 0.0;
  std::pair<double, double> best{best_u(0.0), 0.0};
  for (const std::pair<double, double>& candidate :
       {std::pair{best_u(w_max), w_max}, std::pair{0.0, w_alone}}) {
    if (cost(candidate.first, candidate.second) < cost(best.first, best.second)) best = candidate;
  }
  return best;
}

double Squared(double x) { return x * x; }

// Re-linearisation: at most this many steps, done when both scales move less than 3 %; a scale
// never drops below 5 % of robot.json's (the local slope at 0 is not measurable).
constexpr int kMaxIterations = 4;
constexpr double kSettledRel = 0.03;
constexpr double kMinScale = 0.05;

}  // namespace

TrialVariation ScaledVariation(const TrialVariation& base, double placement, double playback) {
  TrialVariation v = base;
  v.placement_sigma_x_m *= placement;
  v.placement_sigma_y_m *= placement;
  v.placement_sigma_theta_rad *= placement;
  v.motion_speed_sigma_rel *= playback;
  return v;
}

LaunchSpread SpreadOf(const std::vector<KickObservation>& observations) {
  std::vector<double> speeds, directions;
  for (const KickObservation& o : observations) {
    speeds.push_back(o.launch_speed_mps);
    directions.push_back(o.launch_direction_rad);
  }
  const double centre = SummarizeCircular(directions).mean_rad;
  return {RobustSd(speeds), RobustSd(UnwrapAround(directions, centre))};
}

VariationFit FitVariation(const VariationFitSettings& settings,
                          const std::map<std::string, LaunchSpread>& observed,
                          const std::filesystem::path& models) {
  const Robot robot = LoadRobot(settings.robot, models);
  VariationFit fit;
  fit.base = robot.spec.variation;
  fit.fastest_playback = FastestAllowedPlayback(robot);
  const std::string where = (models / "robots" / settings.robot / "robot.json").string();
  if (fit.base.placement_sigma_x_m + fit.base.placement_sigma_y_m +
          fit.base.placement_sigma_theta_rad <= 0.0 ||
      fit.base.motion_speed_sigma_rel <= 0.0) {
    throw InputError(where + ": trial_variation: the placement and playback sigmas must not be 0 "
                             "(the fit scales them)");
  }
  // Re-linearised at the current scales until they settle: a placement error's effect on a
  // kick grows faster than linearly (an off-centre toe), so one linear step overshoots.
  // The playback spread is bounded by the joints: at 3 sigma no motion may exceed a speed limit.
  const double max_playback_scale =
      (fit.fastest_playback - 1.0) / (TrialVariation::kClipSigmas * fit.base.motion_speed_sigma_rel);
  double s_p = 1.0, s_s = std::min(1.0, max_playback_scale);
  std::map<std::string, LaunchSpread> placement, playback;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    placement = Spreads(settings, observed, ScaledVariation(fit.base, s_p, 0.0), models);
    playback = Spreads(settings, observed, ScaledVariation(fit.base, 0.0, s_s), models);
    std::vector<Equation> equations;
    for (const auto& [kick, o] : observed) {
      const LaunchSpread& p = placement.at(kick);
      const LaunchSpread& q = playback.at(kick);
      equations.push_back({Squared(p.sigma_speed_mps / s_p), Squared(q.sigma_speed_mps / s_s),
                           Squared(o.sigma_speed_mps)});
      equations.push_back({Squared(p.sigma_direction_rad / s_p),
                           Squared(q.sigma_direction_rad / s_s), Squared(o.sigma_direction_rad)});
    }
    const auto [u, w] = BoundedFit(equations, Squared(max_playback_scale));
    const double next_p = std::max(kMinScale, std::sqrt(u));
    const double next_s = std::max(kMinScale, std::sqrt(w));
    const bool settled = std::abs(next_p - s_p) <= kSettledRel * s_p &&
                         std::abs(next_s - s_s) <= kSettledRel * s_s;
    s_p = next_p, s_s = next_s;
    fit.iterations = iteration + 1;
    if (settled) break;
  }
  fit.placement_scale = s_p;
  fit.playback_scale = s_s;
  fit.fitted = ScaledVariation(fit.base, fit.placement_scale, fit.playback_scale);
  fit.playback_at_limit = fit.playback_scale >= max_playback_scale * (1.0 - 1e-9);
  const auto fitted = Spreads(settings, observed, fit.fitted, models);
  double sum = 0.0;
  for (const auto& [kick, o] : observed) {
    fit.kicks.push_back({kick, o, placement.at(kick), playback.at(kick), fitted.at(kick)});
    const LaunchSpread& f = fitted.at(kick);
    sum += Squared((f.sigma_speed_mps - o.sigma_speed_mps) / o.sigma_speed_mps);
    sum += Squared((f.sigma_direction_rad - o.sigma_direction_rad) / o.sigma_direction_rad);
  }
  fit.rms_residual_rel = std::sqrt(sum / (2.0 * observed.size()));
  return fit;
}

}  // namespace foresight
