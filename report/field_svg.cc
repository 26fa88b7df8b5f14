#include "report/field_svg.h"

#include <cmath>
#include <string>

namespace foresight {

FieldCanvas::FieldCanvas(const FieldSpec& field, double pixels_per_m, double extra_width_px)
    : field_(field),
      scale_(pixels_per_m),
      width_px_(2.0 * 20.0 + field.carpet_length_m * pixels_per_m + extra_width_px),
      svg_(width_px_, 2.0 * 20.0 + field.carpet_width_m * pixels_per_m) {}

void FieldCanvas::DrawField() {
  svg_.Rect(0, 0, width_px_, height(), "fill:#ffffff");
  svg_.Rect(X(-field_.CarpetHalfLength()), Y(field_.CarpetHalfWidth()), Px(field_.carpet_length_m),
            Px(field_.carpet_width_m), "fill:#3f9b4b");
  DrawGoal(+1.0);
  DrawGoal(-1.0);
  DrawLinesAndPosts();
}

void FieldCanvas::DrawLinesAndPosts() {
  const std::string line =
      "fill:none;stroke:#ffffff;stroke-width:" + SvgWriter::Num(Px(field_.line_width_m));
  const double hx = field_.HalfLength(), hy = field_.HalfWidth();
  svg_.Rect(X(-hx), Y(hy), Px(field_.field_length_m), Px(field_.field_width_m), line);
  svg_.Line(X(0), Y(hy), X(0), Y(-hy), line);
  svg_.Circle(X(0), Y(0), Px(0.75 * field_.field_width_m / 6.0), line);
  const GoalSpec& g = field_.goal;
  for (double side : {1.0, -1.0}) {
    const std::string post = side > 0 ? "fill:#f2d600;stroke:#333;stroke-width:1"
                                      : "fill:#1f5fbf;stroke:#333;stroke-width:1";
    for (double y : {g.post_centre_y_m, -g.post_centre_y_m}) {
      svg_.Circle(X(side * g.post_centre_x_m), Y(y), Px(g.post_radius_m), post);
    }
  }
}

void FieldCanvas::DrawGoal(double side) {
  const GoalSpec& g = field_.goal;
  const double front = side * g.post_centre_x_m, back = side * (g.post_centre_x_m + g.net_depth_m);
  const std::string net = "stroke:#d0d0d0;stroke-width:2";
  svg_.Rect(X(std::min(front, back)), Y(g.post_centre_y_m), Px(g.net_depth_m),
            Px(2.0 * g.post_centre_y_m), "fill:#ffffff;fill-opacity:0.25");
  svg_.Line(X(front), Y(g.post_centre_y_m), X(back), Y(g.post_centre_y_m), net);
  svg_.Line(X(back), Y(g.post_centre_y_m), X(back), Y(-g.post_centre_y_m), net);
  svg_.Line(X(back), Y(-g.post_centre_y_m), X(front), Y(-g.post_centre_y_m), net);
}

void FieldCanvas::DrawRobot(const Pose2& pose, double radius_m, std::string_view colour) {
  const std::string style = "fill:" + std::string(colour) + ";stroke:#111;stroke-width:1.5";
  svg_.Circle(X(pose.p_F.x()), Y(pose.p_F.y()), Px(radius_m), style);
  const Vec2 nose = pose.p_F + radius_m * UnitVector(pose.theta_rad);
  svg_.Line(X(pose.p_F.x()), Y(pose.p_F.y()), X(nose.x()), Y(nose.y()),
            "stroke:#111;stroke-width:2.5");
}

void FieldCanvas::DrawDot(const Vec2& p_F, double radius_px, std::string_view style) {
  svg_.Circle(X(p_F.x()), Y(p_F.y()), radius_px, style);
}

void FieldCanvas::DrawArrow(const Vec2& from_F, const Vec2& to_F, std::string_view colour) {
  const std::string style = "stroke:" + std::string(colour) + ";stroke-width:2.5";
  svg_.Line(X(from_F.x()), Y(from_F.y()), X(to_F.x()), Y(to_F.y()), style);
  const Vec2 d = to_F - from_F;
  if (d.norm() <= 0.0) return;
  const double heading = std::atan2(d.y(), d.x());
  for (double side : {-1.0, 1.0}) {
    const Vec2 barb = to_F - 0.15 * UnitVector(heading + side * 0.45);
    svg_.Line(X(to_F.x()), Y(to_F.y()), X(barb.x()), Y(barb.y()), style);
  }
}

}  // namespace foresight
