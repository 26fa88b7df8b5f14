// Field maps of the paper's experiments, drawn on report/field_svg.h's FieldCanvas:
//   - a cell map: the field cut into square cells, each coloured by a value on a sequential,
//     colour-blind-safe scale (viridis-like), with a colour bar; used for how stable the
//     decision is at each position (stability experiment);
//   - ball paths: for each strategy the ball's positions from one start, kick by kick, joined by
//     lines, like Fig. 3 of Mellmann & Schlotter (strategies experiment).
#pragma once

#include <string>
#include <vector>

#include "common/geometry.h"
#include "models/field_spec.h"

namespace foresight {

struct FieldCellMap {
  std::string title;
  std::string value_label;  // the colour bar's label, e.g. "share of the most frequent decision"
  double cell_size_m = 0.3;
  std::vector<Vec2> cell_centres_F;  // field frame, metres
  std::vector<double> values;        // one per cell; non-finite: the cell is left empty
  double value_lo = 0.0;             // the colour scale's ends (values are clamped to them)
  double value_hi = 1.0;
  double pixels_per_m = 70.0;
};
// Throws std::invalid_argument if cell_centres_F and values differ in length (programming error).
std::string FieldCellMapSvg(const FieldSpec& field, const FieldCellMap& map);

// The colour of `t` in [0, 1] on the map's scale, "#rrggbb" (t clamped). Exposed for tests.
std::string SequentialColour(double t);

struct BallPath {
  std::string name;           // legend text, e.g. "optimal_all: 5 kicks, goal"
  std::vector<Vec2> balls_F;  // the ball's start, then its rest position after each kick
};

struct BallPathsMap {
  std::string title;
  Pose2 robot_start;            // drawn as a robot
  std::vector<BallPath> paths;  // path i in PaletteColour(i); circles at each ball position
  double pixels_per_m = 70.0;
};
std::string BallPathsSvg(const FieldSpec& field, const BallPathsMap& map);

}  // namespace foresight
