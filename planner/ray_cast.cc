#include "planner/ray_cast.h"

#include <algorithm>
#include <cmath>

namespace foresight {

double RayCapsuleEntry(const Vec2& start, const Vec2& dir, const Vec2& a, const Vec2& b,
                       double radius) {
  // The capsule is the union of the two end discs and the rectangle of the segment swept
  // sideways by `radius`; the entry is the earliest entry into any of them.
  const Vec2 axis = b - a;
  const double length = axis.norm();
  if (length <= 0.0) return RayCircleEntry(start, dir, a, radius);
  const Vec2 u = axis / length;
  const double start_along = std::clamp((start - a).dot(u), 0.0, length);
  const Vec2 from_axis = start - (a + start_along * u);
  if (from_axis.squaredNorm() <= radius * radius) {  // starts in contact
    return from_axis.dot(dir) < 0.0 ? 0.0 : kNoHit;
  }
  double best =
      std::min(RayCircleEntry(start, dir, a, radius), RayCircleEntry(start, dir, b, radius));
  const Vec2 normal(-u.y(), u.x());
  const double offset = (start - a).dot(normal);  // signed distance of the start from the line
  const double approach = dir.dot(normal);
  if (std::abs(offset) <= radius) return best;  // beside the body in its slab: only caps count
  if (approach == 0.0 || (offset > 0.0) == (approach > 0.0)) return best;  // moving away
  const double s = (std::abs(offset) - radius) / std::abs(approach);
  const double along = (start + s * dir - a).dot(u);
  if (along >= 0.0 && along <= length) best = std::min(best, s);
  return best;
}

}  // namespace foresight
