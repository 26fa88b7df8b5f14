#include "validation/trial_view.h"

#include <cassert>

#include "common/geometry.h"
#include "report/report_format.h"

namespace foresight {

ViewerNumbers TrialNumbers(const TrialResult& r) {
  const Outcome& o = r.outcome;
  ViewerNumbers rows;
  rows.push_back({"outcome", std::string(CategoryName(o.category)) + ", " +
                                 std::string(OutcomeStatusName(o.status))});
  rows.push_back({"first contact", std::string(ContactName(o.first_contact))});
  if (r.blocked) {
    rows.push_back({"stance", Format("blocked: %.1f mm inside a post, net or robot; not played",
                                     r.stance_overlap_m * 1e3)});
  }
  if (r.touched) {
    rows.push_back({"launch speed", Format("%.3f m/s", r.launch_speed_mps)});
    rows.push_back({"launch direction", Format("%+.2f deg (robot frame)",
                                               r.launch_direction_rad * kRadToDeg)});
    rows.push_back({"launch point", Format("(%.3f, %.3f) m", r.p_F_launch.x(), r.p_F_launch.y())});
    // The strike gave the ball a launch's speed (physics/phases.h); a first touch long before it
    // was a graze that left the ball nearly at rest.
    rows.push_back({"strike", Format("%.3f s (the touch gives a launch's speed)", r.t_strike_s)});
    rows.push_back(
        {"first touch", Format("%.3f s (within 1 mm), %.0f ms before the strike", r.t_first_touch_s,
                               (r.t_strike_s - r.t_first_touch_s) * 1e3)});
  }
  rows.push_back({"rest", Format("(%.3f, %.3f) m", o.p_F_rest.x(), o.p_F_rest.y())});
  rows.push_back({"time to rest", Format("%.2f s after the touch", o.time_s)});
  rows.push_back({"placement error", Format("dx %+.1f mm, dy %+.1f mm, %+.2f deg",
                                            r.draw.placement_dx_m * 1e3,
                                            r.draw.placement_dy_m * 1e3,
                                            r.draw.placement_dtheta_rad * kRadToDeg)});
  rows.push_back({"motion speed", Format("x %.3f", r.draw.speed_factor)});
  rows.push_back({"carpet", Format("x %.3f deceleration", r.draw.carpet_factor)});
  if (r.fell || r.max_tilt_rad > 0.0) {
    rows.push_back({"torso tilt", Format("%.1f deg max%s", r.max_tilt_rad * kRadToDeg,
                                         r.fell ? ", fell" : "")});
  }
  return rows;
}

ViewerTrial TrialView(const TrialResult& result, std::string label) {
  assert(result.scene.has_value());
  ViewerTrial trial;
  trial.label = std::move(label);
  trial.numbers = TrialNumbers(result);
  trial.trace = *result.scene;
  return trial;
}

void AddTrialViews(std::span<const TrialResult> results, ViewerScene& scene) {
  for (std::size_t i = 0; i < results.size(); ++i) {
    scene.trials.push_back(TrialView(results[i], "trial " + std::to_string(i)));
  }
}

}  // namespace foresight
