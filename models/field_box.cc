#include "models/field_box.h"

#include <algorithm>

#include "common/json_reader.h"

namespace foresight {

Vec2 FieldBox::Clamp(const Vec2& p_F) const {
  return Vec2(std::clamp(p_F.x(), x_min_m, x_max_m), std::clamp(p_F.y(), y_min_m, y_max_m));
}

FieldBox ReadFieldBox(const JsonObject& o) {
  o.RejectUnknownKeys({"x_min_m", "x_max_m", "y_min_m", "y_max_m"});
  FieldBox r{o.Number("x_min_m"), o.Number("x_max_m"), o.Number("y_min_m"), o.Number("y_max_m")};
  if (!(r.x_min_m < r.x_max_m)) o.Fail("x_max_m", "must be greater than x_min_m");
  if (!(r.y_min_m < r.y_max_m)) o.Fail("y_max_m", "must be greater than y_min_m");
  return r;
}

}  // namespace foresight
