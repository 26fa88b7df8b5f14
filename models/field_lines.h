// The lines whose crossing decides a kick's category, shared by the coarse model and physics.
//
// A ball counts as out (or in a goal) once it has completely crossed a line: its centre lies
// beyond the line's outer edge by one ball radius (RoboCup SPL rules, "ball out of play").
// The first line the ball's path crosses decides: a goal line between the posts is a goal, any
// other line is out. A ball resting beyond the lines is in a goal if it lies inside the goal's
// box (between the posts' centres, not behind the back net), otherwise out.
#pragma once

#include "common/geometry.h"
#include "models/field_spec.h"
#include "models/outcome.h"

namespace foresight {

struct FieldLines {
  double out_x_m = 0.0;            // |x| beyond this: over a goal line
  double out_y_m = 0.0;            // |y| beyond this: over a side line
  double goal_half_width_m = 0.0;  // |y| below this when crossing a goal line: a goal
  double goal_depth_x_m = 0.0;     // x of the back nets
  // Physics only (the coarse model's ball never leaves the carpet): a ball whose centre is
  // higher than this as it crosses a goal line passes over the crossbar, which is out.
  double goal_max_centre_z_m = 0.0;

  static FieldLines Of(const FieldSpec& field);
};

// Category of a ball at p_F, judged by position alone (no path).
Category ClassifyPosition(const FieldLines& lines, const Vec2& p_F);

// Category of a straight path from `start` along unit `dir` for `length_m`: the first line it
// crosses outward decides; a path that crosses none is classified by where it ends, and one
// that starts out or in a goal keeps that category.
Category ClassifyPath(const FieldLines& lines, const Vec2& start, const Vec2& dir, double length_m);

}  // namespace foresight
