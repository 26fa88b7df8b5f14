#include "planner/first_hit.h"

#include <algorithm>
#include <cmath>

namespace foresight {

namespace {

void HitGoal(const GoalShapes& goal, double ball_radius, const Vec2& start, const Vec2& dir,
             double length, FirstHit& hit) {
  if (DistanceToSegment(goal.bound_centre, start, dir, length) > goal.bound_radius_m) return;
  for (const CircleShape& post : goal.posts) {
    hit.Offer(RayCircleEntry(start, dir, post.centre, post.contact_radius_m), Contact::kPost,
              post.centre, Vec2(1.0, 0.0), 0.0);
  }
  for (const SegmentShape& net : goal.net) {
    hit.Offer(RayCapsuleEntry(start, dir, net.a, net.b, ball_radius), Contact::kNet, net.a, net.u,
              net.length_m);
  }
}

}  // namespace

FirstHit FindFirstHit(const CoarseWorld& world, const Vec2& start, const Vec2& dir,
                      double length_m) {
  FirstHit hit;
  for (const GoalShapes& goal : world.goals) {
    HitGoal(goal, world.ball_radius_m, start, dir, length_m, hit);
  }
  for (const CircleShape& obstacle : world.obstacles) {
    hit.Offer(RayCircleEntry(start, dir, obstacle.centre, obstacle.contact_radius_m),
              Contact::kObstacle, obstacle.centre, Vec2(1.0, 0.0), 0.0);
  }
  return hit;
}

Reflection Reflect(const FirstHit& hit, const Vec2& p_F_hit, const Vec2& dir_F, double e) {
  const double px = p_F_hit.x(), py = p_F_hit.y();
  const double dx = dir_F.x(), dy = dir_F.y();
  const double along =
      std::clamp((px - hit.a.x()) * hit.u.x() + (py - hit.a.y()) * hit.u.y(), 0.0, hit.length_m);
  const double qx = hit.a.x() + along * hit.u.x(), qy = hit.a.y() + along * hit.u.y();
  const double gx = px - qx, gy = py - qy;
  const double gap = std::sqrt(gx * gx + gy * gy);  // the contact distance (> 0)
  const double nx = gx / gap, ny = gy / gap;
  const double k = (1.0 + e) * (dx * nx + dy * ny);
  const double rx = dx - k * nx, ry = dy - k * ny;
  Reflection r;
  r.speed_factor = std::sqrt(rx * rx + ry * ry);
  if (r.speed_factor > 0.0) r.dir_F = Vec2(rx / r.speed_factor, ry / r.speed_factor);
  return r;
}

}  // namespace foresight
