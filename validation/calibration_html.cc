// The calibration report as one HTML page: per kick a table of the fit against the committed
// model, the speed histogram with the fitted normal, its QQ plot, the direction rose and the
// direction histogram; then the rolling deceleration.
#include "validation/calibration_html.h"

#include <cmath>

#include "common/geometry.h"
#include "report/charts.h"
#include "report/html_report.h"
#include "report/report_format.h"
#include "stats/distributions.h"

namespace foresight {

namespace {

std::string WithInterval(double value, const Interval& ci, int decimals, double scale = 1.0) {
  return Fixed(value * scale, decimals) + " [" + Fixed(ci.low * scale, decimals) + ", " +
         Fixed(ci.high * scale, decimals) + "]";
}

std::function<double(double)> NormalDensity(double mean, double sd) {
  return [mean, sd](double x) { return NormalPdf((x - mean) / sd) / sd; };
}

// The launch offset the model gets: fitted (with its standard error and the measured launch
// point), or the committed one kept when the observations have no launch points (a log).
std::string LaunchOffsetText(const KickCalibration& c) {
  if (!c.launch_offset) return "not fitted (no launch points): the committed value is kept";
  const LaunchOffsetFit& f = *c.launch_offset;
  return Fixed(f.offset_m, 3) + " +- " + Fixed(f.standard_error_m, 3) + " (from " +
         std::to_string(f.kicks) + " kicks; launch point at " + Fixed(f.launch_point_m, 3) +
         " m; written to the model)";
}

void KickTable(HtmlReport& html, const CalibrationRun& run, const CalibratedKick& kick) {
  const KickCalibration& c = kick.fit;
  const std::optional<int> base = run.base.Find(c.kick);
  const auto committed = [&](double KickSpec::*field, double scale, int decimals) {
    return base ? Fixed(run.base.kicks[*base].*field * scale, decimals) : std::string("-");
  };
  const std::string fits = "normal (Anderson-Darling p)";
  html.Table(
      {"parameter", "fitted [interval]", "committed model", fits},
      {{"v0 (m/s)", WithInterval(c.speed.mean, c.speed.mean_ci, kKickFileSpeedDecimals),
        committed(&KickSpec::speed_mps, 1.0, kKickFileSpeedDecimals), ""},
       {"sigma_v (m/s)", WithInterval(c.speed.sd, c.speed.sd_ci, kKickFileSpeedDecimals),
        committed(&KickSpec::sigma_speed_mps, 1.0, kKickFileSpeedDecimals),
        NormalityText(c.speed_normality, run.settings.normality_level)},
       {"alpha (deg)",
        WithInterval(c.direction.mean_rad, c.direction.mean_ci_rad, kKickFileAngleDecimals,
                     kRadToDeg),
        committed(&KickSpec::direction_rad, kRadToDeg, kKickFileAngleDecimals), ""},
       {"sigma_alpha (deg, circular)",
        WithInterval(c.direction.sd_rad, c.direction.sd_ci_rad, kKickFileAngleDecimals, kRadToDeg),
        committed(&KickSpec::sigma_direction_rad, kRadToDeg, kKickFileAngleDecimals),
        NormalityText(c.direction_normality, run.settings.normality_level)},
       {"launch offset (m)", LaunchOffsetText(c), committed(&KickSpec::launch_offset_m, 1.0, 3),
        ""}});
}

void KickFigures(HtmlReport& html, const CalibrationRun& run, const CalibratedKick& kick) {
  const KickCalibration& c = kick.fit;
  const std::optional<int> base = run.base.Find(c.kick);
  HistogramChart speeds;
  speeds.title = c.kick + ": launch speed";
  speeds.x_label = "launch speed (m/s)";
  for (const KickObservation& o : kick.observations) speeds.values.push_back(o.launch_speed_mps);
  speeds.density = NormalDensity(c.speed.mean, c.speed.sd);
  speeds.density_label = "fitted N(" + Fixed(c.speed.mean, 3) + ", " + Fixed(c.speed.sd, 3) + "^2)";
  if (base) {
    speeds.markers.push_back(run.base.kicks[*base].speed_mps);
    speeds.markers_label = "committed v0";
  }
  QqChart qq;
  qq.title = c.kick + ": speed QQ plot (normal)";
  qq.unit = "m/s";
  qq.points = c.speed_qq;
  RoseChart rose;
  rose.title = c.kick + ": launch directions";
  for (const KickObservation& o : kick.observations)
    rose.angles_rad.push_back(o.launch_direction_rad);
  rose.fitted_mean_rad = c.direction.mean_rad;
  rose.fitted_sd_rad = c.direction.sd_rad;
  HistogramChart directions;
  directions.title = c.kick + ": launch direction";
  directions.x_label = "direction in the robot frame (deg)";
  for (double a : c.direction_unwrapped_rad) directions.values.push_back(a * kRadToDeg);
  directions.density =
      NormalDensity(c.direction.mean_rad * kRadToDeg, c.direction.sd_rad * kRadToDeg);
  directions.density_label = "N(" + Fixed(c.direction.mean_rad * kRadToDeg, 1) + ", " +
                             Fixed(c.direction.sd_rad * kRadToDeg, 1) + "^2)";
  if (base) {
    directions.markers.push_back(run.base.kicks[*base].direction_rad * kRadToDeg);
    directions.markers_label = "committed alpha";
  }
  html.FigureRow(
      {{HistogramSvg(speeds), "Launch speeds with the fitted normal density."},
       {QqSvg(qq), "Sorted speeds against normal quantiles; a straight line is normal."}});
  html.FigureRow(
      {{RoseSvg(rose), "Directions (up: straight ahead, left: +90 deg); wedge: mean +- sd."},
       {HistogramSvg(directions), "Directions unwrapped around the circular mean."}});
}

void DecelerationSection(HtmlReport& html, const CalibrationRun& run) {
  html.Heading(2, "Rolling deceleration");
  std::vector<std::vector<std::string>> rows;
  const auto row = [&](const std::string& what, const DecelerationFit& fit) {
    rows.push_back({what, WithInterval(fit.deceleration_mps2, fit.ci_mps2, 4),
                    std::to_string(fit.trials), std::to_string(fit.samples),
                    Fixed(fit.residual_sd_mps, 4)});
  };
  if (run.deceleration) row("all kicks (written to the model)", *run.deceleration);
  for (const CalibratedKick& kick : run.kicks) {
    if (kick.fit.deceleration) row(kick.fit.kick, *kick.fit.deceleration);
  }
  html.Table({"balls of", "a (m/s^2) [interval]", "kicks", "points", "residual sd (m/s)"}, rows);
  std::string text =
      "Least squares of speed over time while the ball rolls freely (one "
      "intercept per kick, a shared slope), interval by a bootstrap over kicks. "
      "The committed model says " +
      Fixed(run.base.rolling_deceleration_mps2, 4) + " m/s^2";
  if (run.carpet_deceleration_mps2) {
    text += "; the physics carpet is set to " + Fixed(*run.carpet_deceleration_mps2, 4) +
            " m/s^2 (varied per kick and per patch)";
  }
  html.Paragraph(text + ".");
}

}  // namespace

std::string CalibrationHtml(const CalibrationRun& run) {
  const RunProvenance& p = run.provenance;
  HtmlReport html("Kick calibration: " + run.robot);
  std::vector<std::pair<std::string, std::string>> header{
      {"source", run.source},
      {"robot", run.robot},
      {"seed", std::to_string(p.seed)},
      {"trials per kick", std::to_string(run.trials_per_kick)},
      {"intervals", Fixed(run.settings.confidence * 100.0, 0) + " %, bootstrap " +
                        std::to_string(run.settings.resamples) + " resamples"},
      {"situation", p.Input("situation").empty() ? "-" : p.Input("situation")},
      {"physics", p.Input("physics").empty() ? "-" : p.Input("physics")},
      {"robot base", p.Input("robot_base").empty() ? "-" : p.Input("robot_base")},
      {"field", p.Input("field").empty() ? "-" : p.Input("field")},
      {"committed model", p.Input("base_kicks") + " (" + p.Input("base_kicks_hash") + ")"},
      {"fitted model written to", p.Input("out")}};
  for (auto& row : ProvenanceRows(p)) header.push_back(std::move(row));
  html.KeyValues(header);
  for (const std::string& w : CalibrationWarnings(run)) html.Warning(w);
  for (const CalibratedKick& kick : run.kicks) {
    html.Heading(
        2, "Kick: " + kick.fit.kick + " (" + std::to_string(kick.fit.observations) + " kicks)");
    KickTable(html, run, kick);
    KickFigures(html, run, kick);
  }
  DecelerationSection(html, run);
  html.Paragraph(
      "Speeds: mean with a Student-t interval, standard deviation with a chi-square interval. "
      "Directions: circular mean and circular standard deviation sqrt(-2 ln R) with bootstrap "
      "intervals. Goodness of fit: Anderson-Darling with mean and sd estimated from the same "
      "data (Stephens' case 3; p-values after D'Agostino & Stephens 1986) and Lilliefors' "
      "Kolmogorov-Smirnov test in the JSON.");
  return html.Finish();
}

}  // namespace foresight
