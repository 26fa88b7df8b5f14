// Drawing a field in SVG: carpet, lines, goals with posts and nets, robots, balls, obstacles.
// Field metres (F: x right towards the opponent goal, y up) are mapped to SVG pixels (y down).
#pragma once

#include <string_view>

#include "common/geometry.h"
#include "models/field_spec.h"
#include "report/svg_writer.h"

namespace foresight {

class FieldCanvas {
 public:
  // `extra_width_px` is free space right of the carpet, for a legend.
  FieldCanvas(const FieldSpec& field, double pixels_per_m, double extra_width_px);

  double X(double x_m) const { return margin_ + (x_m + field_.CarpetHalfLength()) * scale_; }
  double Y(double y_m) const { return margin_ + (field_.CarpetHalfWidth() - y_m) * scale_; }
  double Px(double length_m) const { return length_m * scale_; }
  double legend_x() const { return 2.0 * margin_ + field_.carpet_length_m * scale_; }
  double height() const { return 2.0 * margin_ + field_.carpet_width_m * scale_; }

  void DrawField();  // background, carpet, goals, then DrawLinesAndPosts()
  // The field lines and goal posts alone, e.g. again on top of something drawn over the field.
  void DrawLinesAndPosts();
  void DrawRobot(const Pose2& pose, double radius_m, std::string_view colour);
  void DrawDot(const Vec2& p_F, double radius_px, std::string_view style);
  void DrawArrow(const Vec2& from_F, const Vec2& to_F, std::string_view colour);

  SvgWriter& svg() { return svg_; }

 private:
  void DrawGoal(double side);

  const FieldSpec& field_;
  double scale_;
  double width_px_;
  double margin_ = 20.0;
  SvgWriter svg_;
};

}  // namespace foresight
