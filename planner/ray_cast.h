// Where a moving disc of radius r first touches a static shape, for a path
// p(s) = start + s * dir (|dir| = 1, s in metres along the path). The disc touches a circle of
// radius R at c when |p(s) - c| = R + r, and a segment when its distance to p(s) is r. Returns
// the smallest s >= 0 with contact, or +infinity. A ball that starts within the contact distance
// touches the shape at s = 0 if it moves towards it, and not at all if it moves away (a ball
// resting against a net can be kicked away, but never through it).
#pragma once

#include <limits>

#include "common/geometry.h"

namespace foresight {

inline constexpr double kNoHit = std::numeric_limits<double>::infinity();

// First s >= 0 with |start + s dir - centre| = radius, entering from outside; kNoHit otherwise.
inline double RayCircleEntry(const Vec2& start, const Vec2& dir, const Vec2& centre,
                             double radius) {
  const Vec2 m = start - centre;
  const double b = m.dot(dir);
  const double c = m.squaredNorm() - radius * radius;
  if (c <= 0.0) return b < 0.0 ? 0.0 : kNoHit;  // starts in contact: blocked unless leaving
  if (b >= 0.0) return kNoHit;                  // moving away
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return kNoHit;
  return -b - std::sqrt(discriminant);
}

// First s >= 0 where the path comes within `radius` of segment [a, b] (a capsule).
double RayCapsuleEntry(const Vec2& start, const Vec2& dir, const Vec2& a, const Vec2& b,
                       double radius);

}  // namespace foresight
