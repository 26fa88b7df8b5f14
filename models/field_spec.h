// Dimensions of a soccer field, its goals and its ball (models/fields/*.json).
//
// Lengths are between line centres as the RoboCup rules give them. Goal posts stand at
// x = +-post_centre_x_m, y = +-post_centre_y_m; the net runs net_depth_m behind the posts.
#pragma once

#include <filesystem>
#include <string>

namespace foresight {

struct GoalSpec {
  double post_radius_m = 0.0;
  double post_centre_x_m = 0.0;
  double post_centre_y_m = 0.0;
  double net_depth_m = 0.0;
  double net_height_m = 0.0;

  // Half of the free width between the posts' inner surfaces.
  double InnerHalfWidth() const { return post_centre_y_m - post_radius_m; }
};

struct BallSpec {
  double radius_m = 0.0;
  double mass_kg = 0.0;
  // k = I / (m r^2): 2/5 for a solid ball, 2/3 for a thin hollow shell. A ball kicked sliding
  // starts to roll at 1 / (1 + k) of its speed (5/7 solid, 3/5 hollow).
  double inertia_factor = 0.0;
};

struct FieldSpec {
  std::string name;
  double field_length_m = 0.0;  // between the goal lines' centres
  double field_width_m = 0.0;   // between the side lines' centres
  double line_width_m = 0.0;
  double carpet_length_m = 0.0;
  double carpet_width_m = 0.0;
  GoalSpec goal;
  BallSpec ball;
  double default_obstacle_radius_m = 0.0;

  double HalfLength() const { return 0.5 * field_length_m; }
  double HalfWidth() const { return 0.5 * field_width_m; }
  double CarpetHalfLength() const { return 0.5 * carpet_length_m; }
  double CarpetHalfWidth() const { return 0.5 * carpet_width_m; }

  // Throws InputError naming the first bad field and its value.
  void Validate() const;
};

// Loads and validates a field file; errors name the file.
FieldSpec LoadFieldSpec(const std::filesystem::path& file);

}  // namespace foresight
