// The ray casts against circles and capsules, cross-checked against brute-force marching.
#include "planner/ray_cast.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/random.h"

namespace foresight {
namespace {

double SegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

// First s on a fine grid where the distance drops to `radius`; a start in contact is blocked at
// once if the path goes deeper, free if it leaves.
double MarchCapsule(const Vec2& start, const Vec2& dir, const Vec2& a, const Vec2& b, double r) {
  if (SegmentDistance(start, a, b) <= r) {
    return SegmentDistance(start + 1e-7 * dir, a, b) < SegmentDistance(start, a, b) ? 0.0 : kNoHit;
  }
  for (double s = 0.0; s < 10.0; s += 1e-4) {
    if (SegmentDistance(start + s * dir, a, b) <= r) return s;
  }
  return kNoHit;
}

TEST(RayCastTest, CircleEntryIsExact) {
  EXPECT_DOUBLE_EQ(RayCircleEntry(Vec2(0, 0), Vec2(1, 0), Vec2(3, 0), 1.0), 2.0);
  EXPECT_EQ(RayCircleEntry(Vec2(0, 0), Vec2(-1, 0), Vec2(3, 0), 1.0), kNoHit);    // away
  EXPECT_EQ(RayCircleEntry(Vec2(0, 0), Vec2(1, 0), Vec2(3, 1.01), 1.0), kNoHit);  // misses
  EXPECT_EQ(RayCircleEntry(Vec2(2.5, 0.5), Vec2(1, 0), Vec2(3, 0), 1.0), 0.0);  // in, going deeper
  EXPECT_EQ(RayCircleEntry(Vec2(3.5, 0.5), Vec2(1, 0), Vec2(3, 0), 1.0), kNoHit);  // in, leaving
}

TEST(RayCastTest, CapsuleEntryAgreesWithMarching) {
  RandomStream rng(StreamKey(7, 0));
  int hits = 0;
  for (int i = 0; i < 300; ++i) {
    // One draw per statement: the order of a call's arguments is unspecified.
    const double start_x = 4.0 * rng.NextUniform() - 2.0;
    const Vec2 start(start_x, 4.0 * rng.NextUniform() - 2.0);
    const Vec2 dir = UnitVector(2.0 * kPi * rng.NextUniform());
    const double a_x = rng.NextUniform();
    const Vec2 a(a_x, rng.NextUniform());
    const double b_x = rng.NextUniform() + 0.5;
    const Vec2 b(b_x, -rng.NextUniform());
    const double r = 0.05 + 0.2 * rng.NextUniform();
    const double exact = RayCapsuleEntry(start, dir, a, b, r);
    const double marched = MarchCapsule(start, dir, a, b, r);
    if (marched == kNoHit) {
      EXPECT_TRUE(exact == kNoHit || exact > 9.999)
          << i << " exact " << exact << " start " << start.transpose() << " dir " << dir.transpose()
          << " a " << a.transpose() << " b " << b.transpose() << " r " << r;
    } else {
      ++hits;
      EXPECT_NEAR(exact, marched, 2e-4) << i;
    }
  }
  EXPECT_GT(hits, 30);  // the random cases do exercise contacts
}

}  // namespace
}  // namespace foresight
