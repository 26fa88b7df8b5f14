// Where a moving disc of radius r first touches a static shape, for a path
// p(s) = start + s * dir (|dir| = 1, s in metres along the path). The disc touches a circle of
// radius R at c when |p(s) - c| = R + r, and a segment when its distance to p(s) is r. Returns
// the smallest s >= 0 with contact, or +infinity. Starting inside a shape counts as no contact
// for that shape (the ball leaves it), so a ball resting against a net can still be kicked away.
#pragma once

#include <limits>

#include "models/geometry.h"

namespace foresight {

inline constexpr double kNoHit = std::numeric_limits<double>::infinity();

// First s >= 0 with |start + s dir - centre| = radius, entering from outside; kNoHit otherwise.
inline double RayCircleEntry(const Vec2& start, const Vec2& dir, const Vec2& centre,
                             double radius) {
  const Vec2 m = start - centre;
  const double b = m.dot(dir);
  const double c = m.squaredNorm() - radius * radius;
  if (c <= 0.0 || b >= 0.0) return kNoHit;  // inside already, or moving away
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return kNoHit;
  return -b - std::sqrt(discriminant);
}

// First s >= 0 where the path comes within `radius` of segment [a, b] (a capsule).
double RayCapsuleEntry(const Vec2& start, const Vec2& dir, const Vec2& a, const Vec2& b,
                       double radius);

}  // namespace foresight
