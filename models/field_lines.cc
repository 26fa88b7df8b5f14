#include "models/field_lines.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace foresight {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// Path length until the path first leaves |coordinate| <= limit, or kNever.
double ExitDistance(double start, double dir, double limit) {
  if (std::abs(start) > limit) return kNever;  // already beyond: not an outward crossing
  if (dir > 0.0) return (limit - start) / dir;
  if (dir < 0.0) return (-limit - start) / dir;
  return kNever;
}

}  // namespace

FieldLines FieldLines::Of(const FieldSpec& field) {
  const double beyond_line = 0.5 * field.line_width_m + field.ball.radius_m;
  FieldLines lines;
  lines.out_x_m = field.HalfLength() + beyond_line;
  lines.out_y_m = field.HalfWidth() + beyond_line;
  lines.goal_half_width_m = field.goal.post_centre_y_m;
  lines.goal_depth_x_m = field.goal.post_centre_x_m + field.goal.net_depth_m;
  // Under the crossbar (centred at the net's height, as thick as a post) with the whole ball.
  lines.goal_max_centre_z_m =
      field.goal.net_height_m - field.goal.post_radius_m - field.ball.radius_m;
  return lines;
}

Category ClassifyPosition(const FieldLines& lines, const Vec2& p_F) {
  const double ax = std::abs(p_F.x()), ay = std::abs(p_F.y());
  if (ax <= lines.out_x_m && ay <= lines.out_y_m) return Category::kInfield;
  if (ax <= lines.goal_depth_x_m && ay < lines.goal_half_width_m) {
    return p_F.x() > 0.0 ? Category::kOppGoal : Category::kOwnGoal;
  }
  return Category::kOut;
}

Category ClassifyPath(const FieldLines& lines, const Vec2& start, const Vec2& dir,
                      double length_m) {
  // A ball that is already out or in a goal stays so, whatever the kick does (as for `none`).
  const Category at_start = ClassifyPosition(lines, start);
  if (at_start != Category::kInfield) return at_start;
  const double s_x = ExitDistance(start.x(), dir.x(), lines.out_x_m);
  const double s_y = ExitDistance(start.y(), dir.y(), lines.out_y_m);
  if (std::min(s_x, s_y) > length_m) return ClassifyPosition(lines, start + length_m * dir);
  if (s_y < s_x) return Category::kOut;
  const double y_at_line = start.y() + s_x * dir.y();
  if (std::abs(y_at_line) >= lines.goal_half_width_m) return Category::kOut;
  return dir.x() > 0.0 ? Category::kOppGoal : Category::kOwnGoal;
}

}  // namespace foresight
