#include "models/field_spec.h"

#include "common/checks.h"
#include "common/error.h"
#include "common/json_reader.h"

namespace foresight {

// Plausibility bounds (assumption): robot-soccer fields measure metres to tens of metres (SPL
// 9 x 6 m; a human pitch 105 x 68 m), so 200 m bounds a size and anything beyond is a unit error
// or garbage that would overflow the geometry; posts, nets and balls are decimetres.
constexpr double kMaxFieldSizeM = 200.0;
constexpr double kMaxGoalPartM = 5.0;
constexpr double kMaxBallMassKg = 10.0;

void FieldSpec::Validate() const {
  RequirePositive("field_length_m", field_length_m);
  RequireInRange("field_length_m", field_length_m, 0.0, kMaxFieldSizeM);
  RequirePositive("field_width_m", field_width_m);
  RequireInRange("field_width_m", field_width_m, 0.0, kMaxFieldSizeM);
  RequireNonNegative("line_width_m", line_width_m);
  RequireInRange("carpet_length_m", carpet_length_m, field_length_m, 2.0 * kMaxFieldSizeM);
  RequireInRange("carpet_width_m", carpet_width_m, field_width_m, 2.0 * kMaxFieldSizeM);
  RequirePositive("goal.post_radius_m", goal.post_radius_m);
  RequireInRange("goal.post_radius_m", goal.post_radius_m, 0.0, kMaxGoalPartM);
  RequireInRange("goal.post_centre_x_m", goal.post_centre_x_m, 0.5 * field_length_m - line_width_m,
                 0.5 * carpet_length_m);
  RequireInRange("goal.post_centre_y_m", goal.post_centre_y_m, goal.post_radius_m,
                 0.5 * field_width_m);
  RequirePositive("goal.net_depth_m", goal.net_depth_m);
  RequireInRange("goal.net_depth_m", goal.net_depth_m, 0.0, kMaxGoalPartM);
  RequirePositive("goal.net_height_m", goal.net_height_m);
  RequireInRange("goal.net_height_m", goal.net_height_m, 0.0, kMaxGoalPartM);
  RequireInRange("ball.radius_m", ball.radius_m, 1e-3, goal.InnerHalfWidth());
  RequirePositive("ball.mass_kg", ball.mass_kg);
  RequireInRange("ball.mass_kg", ball.mass_kg, 0.0, kMaxBallMassKg);
  // A sphere's mass can lie no farther out than its surface (k = 2/3) and no closer in than a
  // point at its centre (k = 0); every real ball lies between a solid one and a shell.
  RequireInRange("ball.inertia_factor", ball.inertia_factor, 0.4, 2.0 / 3.0);
  RequireInRange("default_obstacle_radius_m", default_obstacle_radius_m, 0.01, 2.0);
}

FieldSpec LoadFieldSpec(const std::filesystem::path& file) {
  JsonDocument doc = JsonDocument::Load(file);
  JsonObject root = doc.Root();
  root.RejectUnknownKeys({"name", "field_length_m", "field_width_m", "line_width_m",
                          "carpet_length_m", "carpet_width_m", "goal", "ball",
                          "default_obstacle_radius_m"});
  FieldSpec spec;
  spec.name = root.String("name");
  spec.field_length_m = root.Number("field_length_m");
  spec.field_width_m = root.Number("field_width_m");
  spec.line_width_m = root.Number("line_width_m");
  spec.carpet_length_m = root.Number("carpet_length_m");
  spec.carpet_width_m = root.Number("carpet_width_m");
  spec.default_obstacle_radius_m = root.Number("default_obstacle_radius_m");

  JsonObject goal = root.Object("goal");
  goal.RejectUnknownKeys(
      {"post_radius_m", "post_centre_x_m", "post_centre_y_m", "net_depth_m", "net_height_m"});
  spec.goal.post_radius_m = goal.Number("post_radius_m");
  spec.goal.post_centre_x_m = goal.Number("post_centre_x_m");
  spec.goal.post_centre_y_m = goal.Number("post_centre_y_m");
  spec.goal.net_depth_m = goal.Number("net_depth_m");
  spec.goal.net_height_m = goal.Number("net_height_m");

  JsonObject ball = root.Object("ball");
  ball.RejectUnknownKeys({"radius_m", "mass_kg", "inertia_factor"});
  spec.ball.radius_m = ball.Number("radius_m");
  spec.ball.mass_kg = ball.Number("mass_kg");
  spec.ball.inertia_factor = ball.Number("inertia_factor");

  WithFile(file.string(), [&] { spec.Validate(); });
  return spec;
}

}  // namespace foresight
