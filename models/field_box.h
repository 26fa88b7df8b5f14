// An axis-aligned box of positions in the field frame F: an opponent's home region, the penalty
// area, a role region, the region a random attack draws a robot from. Shared by match/ and cbr/.
#pragma once

#include "common/geometry.h"

namespace foresight {

class JsonObject;

// Centre positions x in [x_min, x_max], y in [y_min, y_max] (F).
struct FieldBox {
  double x_min_m = 0.0, x_max_m = 0.0, y_min_m = 0.0, y_max_m = 0.0;
  bool Contains(const Vec2& p_F) const {
    return p_F.x() >= x_min_m && p_F.x() <= x_max_m && p_F.y() >= y_min_m && p_F.y() <= y_max_m;
  }
  Vec2 Clamp(const Vec2& p_F) const;
  // The box mirrored in the y axis (x negated).
  FieldBox MirroredX() const { return {-x_max_m, -x_min_m, y_min_m, y_max_m}; }
};

// Reads {"x_min_m", "x_max_m", "y_min_m", "y_max_m"} (min below max, else an InputError naming
// the field).
FieldBox ReadFieldBox(const JsonObject& o);

}  // namespace foresight
