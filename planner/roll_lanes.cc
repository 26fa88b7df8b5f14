#include "planner/roll_lanes.h"

#include <limits>

namespace foresight {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

LaneMask CategoryLanes(Category c) {
  return BroadcastMask(static_cast<std::int64_t>(c));
}

// RayCircleEntry (planner/ray_cast.h).
Lanes CircleEntry(const RollLanesInput& in, const Vec2& centre, double radius) {
  const Lanes mx = in.start_x - centre.x(), my = in.start_y - centre.y();
  const Lanes b = mx * in.dir_x + my * in.dir_y;
  const Lanes c = (mx * mx + my * my) - radius * radius;
  const Lanes discriminant = b * b - c;
  const Lanes root = -b - Sqrt(Select(discriminant < 0.0, Broadcast(0.0), discriminant));
  const Lanes inside = Select(b < 0.0, Broadcast(0.0), Broadcast(kInf));
  const Lanes outside = Select((b >= 0.0) | (discriminant < 0.0), Broadcast(kInf), root);
  return Select(c <= 0.0, inside, outside);
}

// RayCapsuleEntry (planner/ray_cast.cc) with the segment's axis derived in CoarseWorld.
Lanes CapsuleEntry(const RollLanesInput& in, const SegmentShape& net, double radius) {
  if (net.length_m <= 0.0) return CircleEntry(in, net.a, radius);
  const Lanes ax = in.start_x - net.a.x(), ay = in.start_y - net.a.y();
  const Lanes start_along =
      Clamp(ax * net.u.x() + ay * net.u.y(), Broadcast(0.0), Broadcast(net.length_m));
  const Lanes fx = in.start_x - (net.a.x() + start_along * net.u.x());
  const Lanes fy = in.start_y - (net.a.y() + start_along * net.u.y());
  const LaneMask in_contact = (fx * fx + fy * fy) <= radius * radius;
  const Lanes contact =
      Select((fx * in.dir_x + fy * in.dir_y) < 0.0, Broadcast(0.0), Broadcast(kInf));
  Lanes best = Min(CircleEntry(in, net.a, radius), CircleEntry(in, net.b, radius));
  const Lanes offset = ax * net.normal.x() + ay * net.normal.y();
  const Lanes approach = in.dir_x * net.normal.x() + in.dir_y * net.normal.y();
  const LaneMask caps_only =
      (Abs(offset) <= radius) | (approach == 0.0) | ((offset > 0.0) == (approach > 0.0));
  const Lanes s = (Abs(offset) - radius) / Abs(approach);
  const Lanes along = ((in.start_x + s * in.dir_x) - net.a.x()) * net.u.x() +
                      ((in.start_y + s * in.dir_y) - net.a.y()) * net.u.y();
  const LaneMask side = ~caps_only & (along >= 0.0) & (along <= net.length_m);
  best = Select(side, Min(best, s), best);
  return Select(in_contact, contact, best);
}

// HitGoal (planner/ball_roll.cc): the goal's shapes count for lanes whose path comes within
// its bounding circle.
void HitGoal(const GoalShapes& goal, double ball_radius, const RollLanesInput& in, Lanes& hit) {
  const Vec2& p = goal.bound_centre;
  const Lanes along = Clamp((p.x() - in.start_x) * in.dir_x + (p.y() - in.start_y) * in.dir_y,
                            Broadcast(0.0), in.stop_m);
  const Lanes ex = (in.start_x + along * in.dir_x) - p.x();
  const Lanes ey = (in.start_y + along * in.dir_y) - p.y();
  const LaneMask near = ~(Sqrt(ex * ex + ey * ey) > goal.bound_radius_m);
  if (!Any(near)) return;
  Lanes s = Broadcast(kInf);
  for (const CircleShape& post : goal.posts)
    s = Min(s, CircleEntry(in, post.centre, post.contact_radius_m));
  for (const SegmentShape& net : goal.net) s = Min(s, CapsuleEntry(in, net, ball_radius));
  hit = Select(near, Min(hit, s), hit);
}

// ExitDistance (models/field_lines.cc): the numerator of the direction's case, one division.
Lanes ExitDistance(Lanes start, Lanes dir, double limit) {
  const Lanes distance = Select(dir > 0.0, limit - start, -limit - start) / dir;
  const LaneMask never = (Abs(start) > limit) | (dir == 0.0);
  return Select(never, Broadcast(kInf), distance);
}

}  // namespace

LaneMask ClassifyPositionLanes(const FieldLines& lines, Lanes x, Lanes y) {
  const Lanes ax = Abs(x), ay = Abs(y);
  const LaneMask infield = (ax <= lines.out_x_m) & (ay <= lines.out_y_m);
  const LaneMask in_goal = (ax <= lines.goal_depth_x_m) & (ay < lines.goal_half_width_m);
  const LaneMask goal =
      Select(x > 0.0, CategoryLanes(Category::kOppGoal), CategoryLanes(Category::kOwnGoal));
  return Select(infield, CategoryLanes(Category::kInfield),
                Select(in_goal, goal, CategoryLanes(Category::kOut)));
}

RestLanes RollLanes(const CoarseWorld& world, const RollLanesInput& in) {
  Lanes hit = Broadcast(kInf);
  for (const GoalShapes& goal : world.goals) HitGoal(goal, world.ball_radius_m, in, hit);
  for (const CircleShape& obstacle : world.obstacles) {
    hit = Min(hit, CircleEntry(in, obstacle.centre, obstacle.contact_radius_m));
  }
  const Lanes travelled = Min(hit, in.stop_m);
  RestLanes rest;
  rest.x = Select(in.moving, in.start_x + travelled * in.dir_x, in.start_x);
  rest.y = Select(in.moving, in.start_y + travelled * in.dir_y, in.start_y);

  // ClassifyPath: the first line crossed outward decides.
  const FieldLines& lines = world.lines;
  const Lanes s_x = ExitDistance(in.start_x, in.dir_x, lines.out_x_m);
  const Lanes s_y = ExitDistance(in.start_y, in.dir_y, lines.out_y_m);
  const LaneMask crosses_none = Min(s_x, s_y) > travelled;
  const Lanes y_at_line = in.start_y + s_x * in.dir_y;
  const LaneMask wide = (s_y < s_x) | (Abs(y_at_line) >= lines.goal_half_width_m);
  const LaneMask crossing = Select(
      wide, CategoryLanes(Category::kOut),
      Select(in.dir_x > 0.0, CategoryLanes(Category::kOppGoal), CategoryLanes(Category::kOwnGoal)));
  const LaneMask path =
      Select(crosses_none, ClassifyPositionLanes(lines, rest.x, rest.y), crossing);
  const LaneMask starts_inside = in.start_category == CategoryLanes(Category::kInfield);
  rest.category = Select(in.moving & starts_inside, path, in.start_category);
  return rest;
}

}  // namespace foresight
