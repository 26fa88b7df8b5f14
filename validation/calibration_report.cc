#include "validation/calibration_report.h"

#include <algorithm>
#include <cmath>

#include "common/geometry.h"
#include "report/report_format.h"

namespace foresight {

namespace {

// A motion's lowest point may lie this far below the carpet (the meshes' facets) before the
// calibration warns (physics/motion_clearance.h; the shipped motions' test uses the same 1 mm).
constexpr double kClearanceToleranceM = 0.001;


using Json = nlohmann::ordered_json;

Json IntervalJson(const Interval& interval, double scale = 1.0) {
  return Json::array({interval.low * scale, interval.high * scale});
}

Json NormalityJson(const NormalityTest& test, double level) {
  if (test.all_equal) return Json{{"all_values_equal", true}, {"normal_model_fits", nullptr}};
  return Json{{"anderson_darling_a2", test.anderson_darling},
              {"anderson_darling_p", test.anderson_darling_p},
              {"lilliefors_d", test.lilliefors_d},
              {"lilliefors_p", test.lilliefors_p},
              {"normal_model_fits", !test.Rejected(level)}};
}

Json DecelerationJson(const DecelerationFit& fit) {
  return Json{{"deceleration_mps2", fit.deceleration_mps2},
              {"ci_mps2", IntervalJson(fit.ci_mps2)},
              {"trials", fit.trials},
              {"samples", fit.samples},
              {"residual_sd_mps", fit.residual_sd_mps}};
}

Json KickSpecJson(const KickSpec& k) {
  return Json{{"speed_mps", k.speed_mps},
              {"sigma_speed_mps", k.sigma_speed_mps},
              {"direction_deg", k.direction_rad * kRadToDeg},
              {"sigma_direction_deg", k.sigma_direction_rad * kRadToDeg},
              {"launch_offset_m", k.launch_offset_m}};
}

Json LaunchOffsetJson(const LaunchOffsetFit& fit) {
  return Json{{"offset_m", fit.offset_m},
              {"unclamped_offset_m", fit.unclamped_offset_m},
              {"standard_error_m", fit.standard_error_m},
              {"kicks", fit.kicks},
              {"launch_point_m", fit.launch_point_m},
              {"rest_distance_m", fit.rest_distance_m}};
}

// How many of the kick's trials drew their placement again because the ball lay inside the
// robot (physics/ball_placement.h); 0 for a CSV log.
int PlacementRedrawn(const CalibratedKick& kick) {
  return static_cast<int>(std::count_if(kick.draws.begin(), kick.draws.end(),
                                        [](const TrialDraw& d) { return d.placement_redraws > 0; }));
}

Json KickJson(const CalibrationRun& run, const CalibratedKick& kick) {
  const KickCalibration& c = kick.fit;
  const double level = run.settings.normality_level;
  Json j{{"name", c.kick},          {"observations", c.observations},
         {"missed", kick.missed},   {"fell", kick.fell},
         {"blocked", kick.blocked}, {"placement_redrawn", PlacementRedrawn(kick)}};
  if (const auto i = run.base.Find(c.kick)) j["committed"] = KickSpecJson(run.base.kicks[*i]);
  j["speed"] = Json{{"mean_mps", c.speed.mean},
                    {"mean_ci_mps", IntervalJson(c.speed.mean_ci)},
                    {"sd_mps", c.speed.sd},
                    {"sd_ci_mps", IntervalJson(c.speed.sd_ci)},
                    {"skewness", c.speed.skewness},
                    {"excess_kurtosis", c.speed.excess_kurtosis},
                    {"normality", NormalityJson(c.speed_normality, level)}};
  j["direction"] = Json{{"mean_deg", c.direction.mean_rad * kRadToDeg},
                        {"mean_ci_deg", IntervalJson(c.direction.mean_ci_rad, kRadToDeg)},
                        {"circular_sd_deg", c.direction.sd_rad * kRadToDeg},
                        {"circular_sd_ci_deg", IntervalJson(c.direction.sd_ci_rad, kRadToDeg)},
                        {"resultant_length", c.direction.resultant_length},
                        {"normality", NormalityJson(c.direction_normality, level)}};
  j["deceleration"] = c.deceleration ? DecelerationJson(*c.deceleration) : Json(nullptr);
  j["launch_offset"] = c.launch_offset ? LaunchOffsetJson(*c.launch_offset) : Json(nullptr);
  return j;
}

}  // namespace

std::vector<std::string> CalibrationWarnings(const CalibrationRun& run) {
  std::vector<std::string> warnings;
  const double level = run.settings.normality_level;
  for (const CalibratedKick& kick : run.kicks) {
    const KickCalibration& c = kick.fit;
    if (c.speed_normality.Rejected(level)) {
      warnings.push_back(
          c.kick + ": the normal model does not fit the launch speeds (Anderson-Darling A*2 = " +
          Fixed(c.speed_normality.anderson_darling, 3) +
          ", p = " + Fixed(c.speed_normality.anderson_darling_p, 4) + ", skewness " +
          Fixed(c.speed.skewness, 2) + ", excess kurtosis " + Fixed(c.speed.excess_kurtosis, 2) +
          "); sigma_v summarises the spread only roughly");
    }
    if (c.direction_normality.Rejected(level)) {
      warnings.push_back(
          c.kick + ": the normal model does not fit the launch directions (Anderson-Darling p = " +
          Fixed(c.direction_normality.anderson_darling_p, 4) + ")");
    }
    if (c.launch_offset && c.launch_offset->unclamped_offset_m < 0.0) {
      warnings.push_back(c.kick + ": the balls rested " +
                         Fixed(-100.0 * c.launch_offset->unclamped_offset_m, 1) +
                         " cm short of v0^2/2a on average; the launch offset is clamped at 0");
    }
    if (!c.launch_offset) {
      warnings.push_back(c.kick +
                         ": no launch points (a log has none, or no ball rested without "
                         "a contact); the kick keeps the base model's launch offset");
    }
    if (kick.clearance && kick.clearance->lowest_m < -kClearanceToleranceM) {
      warnings.push_back(
          c.kick + ": its motion takes " + kick.clearance->link_name + " " +
          Fixed(-1000.0 * kick.clearance->lowest_m, 0) + " mm below the carpet at " +
          Fixed(kick.clearance->t_s, 2) +
          " s (the kicking robot touches only the ball, so nothing stops it); a real robot "
          "cannot kick like this, so the fit is not a real robot's kick");
    }
    if (kick.missed > 0) {
      warnings.push_back(c.kick + ": the robot missed the ball in " + std::to_string(kick.missed) +
                         " trials; they are not in the fit");
    }
    if (kick.fell > 0) {
      warnings.push_back(c.kick + ": the robot fell in " + std::to_string(kick.fell) +
                         " trials; they are not in the fit");
    }
    if (kick.blocked > 0) {
      warnings.push_back(
          c.kick + ": a post, net or obstacle robot stood where the robot must stand in " +
          std::to_string(kick.blocked) + " trials (blocked, not played); they are not in the fit");
    }
  }
  if (run.speeds_from_rest > 0) {
    warnings.push_back(std::to_string(run.speeds_from_rest) +
                       " rows had no launch speed; it was derived from the rest position as "
                       "sqrt(2 a (d - launch offset)) with " +
                       (run.deceleration ? "the fitted deceleration " +
                                               Fixed(run.deceleration->deceleration_mps2, 4)
                                         : "the committed deceleration " +
                                               Fixed(run.base.rolling_deceleration_mps2, 4)) +
                       " m/s^2");
  }
  if (!run.deceleration) {
    warnings.push_back(
        "the rolling deceleration could not be fitted (no trajectories and no "
        "rows with both launch and rest); the model keeps " +
        Fixed(run.base.rolling_deceleration_mps2, 4) + " m/s^2");
  }
  return warnings;
}

std::string NormalityText(const NormalityTest& test, double level) {
  if (test.all_equal) return "n/a (all values equal)";
  return std::string(test.Rejected(level) ? "no" : "yes") +
         " (AD p = " + Fixed(test.anderson_darling_p, 3) + ")";
}

std::string CalibrationText(const CalibrationRun& run) {
  const int pct = static_cast<int>(std::lround(run.settings.confidence * 100.0));
  std::string out = "calibration of " + run.robot + " from " + run.source + " (" +
                    std::to_string(pct) + " % intervals)\n";
  for (const CalibratedKick& kick : run.kicks) {
    const KickCalibration& c = kick.fit;
    out += "  " + c.kick + " (" + std::to_string(c.observations) + " kicks): v0 " +
           Fixed(c.speed.mean, 3) + " m/s [" + Fixed(c.speed.mean_ci.low, 3) + ", " +
           Fixed(c.speed.mean_ci.high, 3) + "], sigma_v " + Fixed(c.speed.sd, 3) + " [" +
           Fixed(c.speed.sd_ci.low, 3) + ", " + Fixed(c.speed.sd_ci.high, 3) + "]; alpha " +
           Fixed(c.direction.mean_rad * kRadToDeg, 1) + " deg [" +
           Fixed(c.direction.mean_ci_rad.low * kRadToDeg, 1) + ", " +
           Fixed(c.direction.mean_ci_rad.high * kRadToDeg, 1) + "], sigma_alpha " +
           Fixed(c.direction.sd_rad * kRadToDeg, 1) + " deg [" +
           Fixed(c.direction.sd_ci_rad.low * kRadToDeg, 1) + ", " +
           Fixed(c.direction.sd_ci_rad.high * kRadToDeg, 1) +
           "]; normal speeds: " + NormalityText(c.speed_normality, run.settings.normality_level);
    if (c.launch_offset) {
      out += "; launch offset " + Fixed(c.launch_offset->offset_m, 3) + " m (+- " +
             Fixed(c.launch_offset->standard_error_m, 3) + ", launch point at " +
             Fixed(c.launch_offset->launch_point_m, 3) + " m)";
    }
    if (const int redrawn = PlacementRedrawn(kick); redrawn > 0) {
      out += "; placement drawn again (ball inside the robot) in " + std::to_string(redrawn) +
             " trials";
    }
    out += "\n";
  }
  if (run.deceleration) {
    out += "  rolling deceleration " + Fixed(run.deceleration->deceleration_mps2, 4) + " m/s^2 [" +
           Fixed(run.deceleration->ci_mps2.low, 4) + ", " +
           Fixed(run.deceleration->ci_mps2.high, 4) + "]";
    if (run.carpet_deceleration_mps2) {
      out += " (carpet set to " + Fixed(*run.carpet_deceleration_mps2, 4) + ")";
    }
    out += "\n";
  }
  for (const std::string& w : CalibrationWarnings(run)) out += "  warning: " + w + "\n";
  return out;
}

Json CalibrationJson(const CalibrationRun& run) {
  const RunProvenance& p = run.provenance;
  Json j{{"tool", "foresight calibrate"},
         {"version", p.version},
         {"robot", run.robot},
         {"source", run.source},
         {"seed", p.seed},
         {"trials_per_kick", run.trials_per_kick},
         {"confidence", run.settings.confidence},
         {"bootstrap_resamples", run.settings.resamples},
         {"normality_level", run.settings.normality_level},
         {"files", InputsJson(p)},
         {"run_time_s", p.run_time_s}};
  j["kicks"] = Json::array();
  for (const CalibratedKick& kick : run.kicks) j["kicks"].push_back(KickJson(run, kick));
  j["deceleration"] = run.deceleration ? DecelerationJson(*run.deceleration) : Json(nullptr);
  j["carpet_deceleration_mps2"] =
      run.carpet_deceleration_mps2 ? Json(*run.carpet_deceleration_mps2) : Json(nullptr);
  j["warnings"] = CalibrationWarnings(run);
  Json fitted = Json::array();
  for (const KickSpec& k : run.fitted.kicks) {
    Json spec{{"name", k.name}};
    spec.update(KickSpecJson(k));
    fitted.push_back(spec);
  }
  j["fitted_model"] = Json{{"robot", run.fitted.robot},
                           {"rolling_deceleration_mps2", run.fitted.rolling_deceleration_mps2},
                           {"kicks", fitted}};
  return j;
}

std::string CalibrationObservationsCsv(const CalibrationRun& run) {
  std::string out =
      "kick,index,launch_speed_mps,launch_direction_deg,roll_distance_m,rolling_samples,"
      "placement_dx_m,placement_dy_m,placement_dtheta_deg,speed_factor,carpet_factor,"
      "placement_redraws\n";
  for (const CalibratedKick& kick : run.kicks) {
    for (std::size_t i = 0; i < kick.observations.size(); ++i) {
      const KickObservation& o = kick.observations[i];
      out += kick.fit.kick + "," + std::to_string(i) + "," + Fixed(o.launch_speed_mps, 6) + "," +
             Fixed(o.launch_direction_rad * kRadToDeg, 4) + "," +
             (o.has_roll_distance ? Fixed(o.roll_distance_m, 6) : "") + "," +
             std::to_string(o.rolling.size()) + ",";
      if (i < kick.draws.size()) {
        const TrialDraw& d = kick.draws[i];
        out += Fixed(d.placement_dx_m, 6) + "," + Fixed(d.placement_dy_m, 6) + "," +
               Fixed(d.placement_dtheta_rad * kRadToDeg, 4) + "," + Fixed(d.speed_factor, 6) + "," +
               Fixed(d.carpet_factor, 6) + "," + std::to_string(d.placement_redraws) + "\n";
      } else {
        out += ",,,,,\n";
      }
    }
  }
  return out;
}

std::string CalibrationSummaryCsv(const CalibrationRun& run) {
  std::string out =
      "kick,observations,speed_mps,speed_ci_low,speed_ci_high,sigma_speed_mps,sigma_ci_low,"
      "sigma_ci_high,direction_deg,direction_ci_low,direction_ci_high,sigma_direction_deg,"
      "sigma_direction_ci_low,sigma_direction_ci_high,speed_ad_p,direction_ad_p,launch_offset_m\n";
  for (const CalibratedKick& kick : run.kicks) {
    const KickCalibration& c = kick.fit;
    const double d = kRadToDeg;
    out += c.kick + "," + std::to_string(c.observations) + "," + Fixed(c.speed.mean, 6) + "," +
           Fixed(c.speed.mean_ci.low, 6) + "," + Fixed(c.speed.mean_ci.high, 6) + "," +
           Fixed(c.speed.sd, 6) + "," + Fixed(c.speed.sd_ci.low, 6) + "," +
           Fixed(c.speed.sd_ci.high, 6) + "," + Fixed(c.direction.mean_rad * d, 4) + "," +
           Fixed(c.direction.mean_ci_rad.low * d, 4) + "," +
           Fixed(c.direction.mean_ci_rad.high * d, 4) + "," + Fixed(c.direction.sd_rad * d, 4) +
           "," + Fixed(c.direction.sd_ci_rad.low * d, 4) + "," +
           Fixed(c.direction.sd_ci_rad.high * d, 4) + "," +
           Fixed(c.speed_normality.anderson_darling_p, 6) + "," +
           Fixed(c.direction_normality.anderson_darling_p, 6) + "," +
           (c.launch_offset ? Fixed(c.launch_offset->offset_m, 6) : "") + "\n";
  }
  return out;
}

}  // namespace foresight
