// The coarse ball roll of kLanes samples at once (planner/lanes.h): RollBall's first contact with
// posts, nets and obstacles, the stop on open carpet, ClassifyPath's category and, with the
// world's rebounds on, the reflections leg by leg (planner/ball_roll.h, planner/first_hit.h,
// planner/ray_cast.h, models/field_lines.h), written with the same operations in the same order,
// so every lane has the scalar code's bits on any instruction set.
//
// Branches of the scalar code become selects: every lane computes every case and keeps its
// own. The goals are the exception: their posts and nets are only tested when the path of some
// lane passes within a goal's bounding circle (most paths pass none).
#pragma once

#include "planner/coarse_world.h"
#include "planner/lanes.h"

namespace foresight {

// Categories in lanes: the values of Category.
struct RestLanes {
  Lanes x;
  Lanes y;
  LaneMask category;
};

// Starting points, unit directions (turned), stop distances on open carpet (StopDistance plus the
// launch offset) and, per lane, whether the ball moves at all (launch speed > 0) and the category
// of its start (ClassifyPosition). The launch speed and offset are read when the world's rebounds
// are on (RollBall's rebounding roll, leg by leg).
struct RollLanesInput {
  Lanes start_x, start_y;
  Lanes dir_x, dir_y;
  Lanes stop_m;
  LaneMask moving;
  LaneMask start_category;
  Lanes speed_mps;
  Lanes offset_m;
};

RestLanes RollLanes(const CoarseWorld& world, const RollLanesInput& in);

// ClassifyPosition (models/field_lines.h) in lanes.
LaneMask ClassifyPositionLanes(const FieldLines& lines, Lanes x, Lanes y);

}  // namespace foresight
