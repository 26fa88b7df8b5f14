#include "planner/coarse_world.h"

#include <cassert>
#include <cmath>

namespace foresight {

namespace {

GoalShapes MakeGoal(const FieldSpec& field, double side) {
  const GoalSpec& g = field.goal;
  const double r = field.ball.radius_m;
  const double x_front = side * g.post_centre_x_m;
  const double x_back = side * (g.post_centre_x_m + g.net_depth_m);
  GoalShapes goal;
  goal.posts[0] = {Vec2(x_front, g.post_centre_y_m), g.post_radius_m + r, Contact::kPost};
  goal.posts[1] = {Vec2(x_front, -g.post_centre_y_m), g.post_radius_m + r, Contact::kPost};
  goal.net[0] =
      SegmentShape::Between(Vec2(x_front, g.post_centre_y_m), Vec2(x_back, g.post_centre_y_m));
  goal.net[1] =
      SegmentShape::Between(Vec2(x_back, g.post_centre_y_m), Vec2(x_back, -g.post_centre_y_m));
  goal.net[2] =
      SegmentShape::Between(Vec2(x_back, -g.post_centre_y_m), Vec2(x_front, -g.post_centre_y_m));
  goal.bound_centre = Vec2(0.5 * (x_front + x_back), 0.0);
  const double half_depth = 0.5 * g.net_depth_m + g.post_radius_m;
  goal.bound_radius_m = std::hypot(half_depth, g.post_centre_y_m + g.post_radius_m) + r;
  goal.bound_distance_sq_max = SquaredBound(goal.bound_radius_m);
  return goal;
}

}  // namespace

double SquaredBound(double r) {
  // r * r is within an ulp of the answer; step to it.
  double d = r * r;
  while (d > 0.0 && std::sqrt(d) > r) d = std::nextafter(d, 0.0);
  while (std::sqrt(std::nextafter(d, INFINITY)) <= r) d = std::nextafter(d, INFINITY);
  return d;
}

SegmentShape SegmentShape::Between(const Vec2& a, const Vec2& b) {
  SegmentShape s;
  s.a = a;
  s.b = b;
  const Vec2 axis = b - a;
  s.length_m = axis.norm();
  if (s.length_m > 0.0) {
    s.u = axis / s.length_m;
    s.normal = Vec2(-s.u.y(), s.u.x());
  }
  return s;
}

CoarseWorld CoarseWorld::Build(const Scene& scene) {
  assert(scene.field != nullptr);
  const FieldSpec& field = *scene.field;
  CoarseWorld world;
  world.ball_radius_m = field.ball.radius_m;
  world.deceleration_mps2 = scene.rolling_deceleration_mps2;
  world.lines = FieldLines::Of(field);
  world.rebounds = scene.rebounds;
  world.goals[0] = MakeGoal(field, +1.0);
  world.goals[1] = MakeGoal(field, -1.0);
  for (const Obstacle& o : scene.obstacles) {
    world.obstacles.push_back({o.p_F, o.radius_m + field.ball.radius_m, Contact::kObstacle});
  }
  return world;
}

}  // namespace foresight
