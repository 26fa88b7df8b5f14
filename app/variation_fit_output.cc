#include "app/variation_fit_output.h"

#include <cstdio>

#include "common/geometry.h"

namespace foresight {

namespace {

nlohmann::json SpreadJson(const LaunchSpread& s) {
  return {{"sigma_speed_mps", s.sigma_speed_mps},
          {"sigma_direction_deg", s.sigma_direction_rad * kRadToDeg}};
}

nlohmann::json VariationJson(const TrialVariation& v) {
  return {{"placement_sigma_x_m", v.placement_sigma_x_m},
          {"placement_sigma_y_m", v.placement_sigma_y_m},
          {"placement_sigma_theta_deg", v.placement_sigma_theta_rad * kRadToDeg},
          {"motion_speed_sigma_rel", v.motion_speed_sigma_rel}};
}

std::string Row(const char* label, const LaunchSpread& s) {
  char line[128];
  std::snprintf(line, sizeof line, "    %-16s sigma_v %.4f m/s  sigma_alpha %.2f deg\n", label,
                s.sigma_speed_mps, s.sigma_direction_rad * kRadToDeg);
  return line;
}

}  // namespace

nlohmann::json VariationFitJson(const std::string& robot, const std::string& source,
                                const VariationFit& fit) {
  nlohmann::json kicks = nlohmann::json::array();
  for (const KickSpreadFit& k : fit.kicks) {
    kicks.push_back({{"kick", k.kick},
                     {"observed", SpreadJson(k.observed)},
                     {"placement_only", SpreadJson(k.placement_only)},
                     {"playback_only", SpreadJson(k.playback_only)},
                     {"fitted", SpreadJson(k.fitted)}});
  }
  return {{"robot", robot},
          {"source", source},
          {"spread_measure", "robust sd (1.4826 x median absolute deviation)"},
          {"trial_variation", VariationJson(fit.fitted)},
          {"fit",
           {{"base_trial_variation", VariationJson(fit.base)},
            {"placement_scale", fit.placement_scale},
            {"playback_scale", fit.playback_scale},
            {"iterations", fit.iterations},
            {"rms_residual_rel", fit.rms_residual_rel},
            {"playback_at_limit", fit.playback_at_limit},
            {"fastest_playback", fit.fastest_playback},
            {"kicks", kicks}}}};
}

std::string VariationFitText(const VariationFit& fit) {
  char head[256];
  std::snprintf(head, sizeof head,
                "fitted causes: placement x %.3f of robot.json's (%.4f m, %.4f m, %.2f deg), "
                "playback speed sigma %.4f (x %.3f); %d linearisations\n",
                fit.placement_scale, fit.fitted.placement_sigma_x_m,
                fit.fitted.placement_sigma_y_m, fit.fitted.placement_sigma_theta_rad * kRadToDeg,
                fit.fitted.motion_speed_sigma_rel, fit.playback_scale, fit.iterations);
  std::string text = head;
  for (const KickSpreadFit& k : fit.kicks) {
    text += "  " + k.kick + " (robust sds):\n" + Row("observed", k.observed) +
            Row("placement only", k.placement_only) + Row("playback only", k.playback_only) +
            Row("physics, fitted", k.fitted);
  }
  char tail[160];
  std::snprintf(tail, sizeof tail, "RMS relative residual of the fitted sigmas: %.1f %%\n",
                100.0 * fit.rms_residual_rel);
  text += tail;
  if (fit.playback_at_limit) {
    text += "  warning: the observed speed spread asks for more playback variation than the "
            "joints' speed limits allow; it is held at the limit and the speed spread is not "
            "reproduced\n";
  }
  return text;
}

}  // namespace foresight
