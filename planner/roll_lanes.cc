#include "planner/roll_lanes.h"

#include <limits>

namespace foresight {

namespace {

// The small tests of the straight roll are forced inline ([[gnu::always_inline]]): called apart,
// every one reloads its lanes from memory and the roll's short chains cannot overlap.
constexpr double kInf = std::numeric_limits<double>::infinity();

LaneMask CategoryLanes(Category c) {
  return BroadcastMask(static_cast<std::int64_t>(c));
}

// RayCircleEntry (planner/ray_cast.h).
[[gnu::always_inline]] inline Lanes CircleEntry(const RollLanesInput& in, const Vec2& centre, double radius) {
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

// HitGoal (planner/first_hit.cc): the goal's shapes count for lanes whose path comes within
// its bounding circle.
[[gnu::always_inline]] inline LaneMask NearGoal(const GoalShapes& goal, const RollLanesInput& in) {
  const Vec2& p = goal.bound_centre;
  const Lanes along = Clamp((p.x() - in.start_x) * in.dir_x + (p.y() - in.start_y) * in.dir_y,
                            Broadcast(0.0), in.stop_m);
  const Lanes ex = (in.start_x + along * in.dir_x) - p.x();
  const Lanes ey = (in.start_y + along * in.dir_y) - p.y();
  // ~(Sqrt(ex * ex + ey * ey) > goal.bound_radius_m), exactly, without the root.
  return ~((ex * ex + ey * ey) > goal.bound_distance_sq_max);
}

[[gnu::always_inline]] inline void HitGoal(const GoalShapes& goal, double ball_radius, const RollLanesInput& in, Lanes& hit) {
  const LaneMask near = NearGoal(goal, in);
  if (!Any(near)) return;
  Lanes s = Broadcast(kInf);
  for (const CircleShape& post : goal.posts)
    s = Min(s, CircleEntry(in, post.centre, post.contact_radius_m));
  for (const SegmentShape& net : goal.net) s = Min(s, CapsuleEntry(in, net, ball_radius));
  hit = Select(near, Min(hit, s), hit);
}

// ExitDistance (models/field_lines.cc): the numerator of the direction's case, one division.
[[gnu::always_inline]] inline Lanes ExitDistance(Lanes start, Lanes dir, double limit) {
  const Lanes distance = Select(dir > 0.0, limit - start, -limit - start) / dir;
  const LaneMask never = (Abs(start) > limit) | (dir == 0.0);
  return Select(never, Broadcast(kInf), distance);
}

// ClassifyPath for a path that starts infield: the first line crossed outward decides, else the
// end (end_x, end_y) does.
[[gnu::always_inline]] inline LaneMask PathCategory(const FieldLines& lines, const RollLanesInput& in, Lanes travelled,
                      Lanes end_x, Lanes end_y) {
  const Lanes s_x = ExitDistance(in.start_x, in.dir_x, lines.out_x_m);
  const Lanes s_y = ExitDistance(in.start_y, in.dir_y, lines.out_y_m);
  const LaneMask crosses_none = Min(s_x, s_y) > travelled;
  const Lanes y_at_line = in.start_y + s_x * in.dir_y;
  const LaneMask wide = (s_y < s_x) | (Abs(y_at_line) >= lines.goal_half_width_m);
  const LaneMask crossing = Select(
      wide, CategoryLanes(Category::kOut),
      Select(in.dir_x > 0.0, CategoryLanes(Category::kOppGoal), CategoryLanes(Category::kOwnGoal)));
  return Select(crosses_none, ClassifyPositionLanes(lines, end_x, end_y), crossing);
}

// FirstHit (planner/first_hit.h) in lanes: the first contact and its shape as a segment.
struct HitLanes {
  Lanes s = Broadcast(kInf);
  Lanes ax = Broadcast(0.0), ay = Broadcast(0.0);
  Lanes ux = Broadcast(1.0), uy = Broadcast(0.0);
  Lanes length_m = Broadcast(0.0);
  Lanes e = Broadcast(0.0);

  // FirstHit::Offer in the lanes of `consider`.
  void Offer(LaneMask consider, Lanes candidate, const Vec2& a, const Vec2& u, double length,
             double restitution) {
    const LaneMask better = consider & (candidate < s);
    s = Select(better, candidate, s);
    ax = Select(better, Broadcast(a.x()), ax);
    ay = Select(better, Broadcast(a.y()), ay);
    ux = Select(better, Broadcast(u.x()), ux);
    uy = Select(better, Broadcast(u.y()), uy);
    length_m = Select(better, Broadcast(length), length_m);
    e = Select(better, Broadcast(restitution), e);
  }
};

// FindFirstHit (planner/first_hit.cc) in lanes.
HitLanes FindFirstHitLanes(const CoarseWorld& world, const RollLanesInput& in) {
  HitLanes hit;
  const LaneMask all = BroadcastMask(-1);
  for (const GoalShapes& goal : world.goals) {
    const LaneMask near = NearGoal(goal, in);
    if (!Any(near)) continue;
    for (const CircleShape& post : goal.posts) {
      hit.Offer(near, CircleEntry(in, post.centre, post.contact_radius_m), post.centre,
                Vec2(1.0, 0.0), 0.0, world.rebounds.post);
    }
    for (const SegmentShape& net : goal.net) {
      hit.Offer(near, CapsuleEntry(in, net, world.ball_radius_m), net.a, net.u, net.length_m,
                world.rebounds.net);
    }
  }
  for (const CircleShape& obstacle : world.obstacles) {
    hit.Offer(all, CircleEntry(in, obstacle.centre, obstacle.contact_radius_m), obstacle.centre,
              Vec2(1.0, 0.0), 0.0, world.rebounds.robot);
  }
  return hit;
}

// SpeedAfter (planner/ball_roll.cc) in lanes.
Lanes SpeedAfter(Lanes speed, double a, Lanes offset, Lanes travelled) {
  const Lanes rolled = Max(Broadcast(0.0), travelled - offset);
  return Sqrt(Max(Broadcast(0.0), speed * speed - 2.0 * a * rolled));
}

// RollRebounding (planner/ball_roll.cc) in lanes: every lane still rebounding rolls its next leg;
// leg k of a lane follows its k-th contact.
RestLanes RollReboundingLanes(const CoarseWorld& world, const RollLanesInput& in) {
  const double a = world.deceleration_mps2;
  const LaneMask infield = CategoryLanes(Category::kInfield);
  RestLanes rest{in.start_x, in.start_y, in.start_category};
  LaneMask rolling = in.moving;
  // Lanes that do not move, or start out or in a goal, keep their start's category.
  LaneMask decided = ~(in.moving & (in.start_category == infield));
  RollLanesInput leg = in;
  LaneMask leg_start_category = in.start_category;
  for (int k = 0;; ++k) {
    const HitLanes hit = FindFirstHitLanes(world, leg);
    const Lanes travelled = Min(hit.s, leg.stop_m);
    const Lanes end_x = leg.start_x + travelled * leg.dir_x;
    const Lanes end_y = leg.start_y + travelled * leg.dir_y;
    const LaneMask category =
        Select(leg_start_category == infield,
               PathCategory(world.lines, leg, travelled, end_x, end_y), leg_start_category);
    const LaneMask decides = rolling & ~decided & (category != infield);
    rest.category = Select(decides, category, rest.category);
    decided |= decides;
    rest.x = Select(rolling, end_x, rest.x);
    rest.y = Select(rolling, end_y, rest.y);
    rolling &= hit.s <= leg.stop_m;
    if (!Any(rolling) || k == world.rebounds.max_contacts) break;
    // Reflect (planner/first_hit.cc).
    const Lanes along =
        Clamp((end_x - hit.ax) * hit.ux + (end_y - hit.ay) * hit.uy, Broadcast(0.0), hit.length_m);
    const Lanes gx = end_x - (hit.ax + along * hit.ux), gy = end_y - (hit.ay + along * hit.uy);
    const Lanes gap = Sqrt(gx * gx + gy * gy);
    const Lanes nx = gx / gap, ny = gy / gap;
    const Lanes kn = (1.0 + hit.e) * (leg.dir_x * nx + leg.dir_y * ny);
    const Lanes rx = leg.dir_x - kn * nx, ry = leg.dir_y - kn * ny;
    const Lanes factor = Sqrt(rx * rx + ry * ry);
    const Lanes v_after = SpeedAfter(leg.speed_mps, a, leg.offset_m, travelled) * factor;
    rolling &= v_after > 0.0;
    if (!Any(rolling)) break;
    leg.start_x = Select(rolling, end_x, leg.start_x);
    leg.start_y = Select(rolling, end_y, leg.start_y);
    leg.dir_x = Select(rolling, rx / factor, leg.dir_x);
    leg.dir_y = Select(rolling, ry / factor, leg.dir_y);
    leg.speed_mps = Select(rolling, v_after, leg.speed_mps);
    leg.offset_m = Broadcast(0.0);
    leg.stop_m = Select(rolling, leg.speed_mps * leg.speed_mps / (2.0 * a), leg.stop_m);
    leg_start_category = ClassifyPositionLanes(world.lines, leg.start_x, leg.start_y);
  }
  rest.category = Select(decided, rest.category, infield);
  return rest;
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
  if (world.rebounds.enabled) return RollReboundingLanes(world, in);
  Lanes hit = Broadcast(kInf);
  for (const GoalShapes& goal : world.goals) HitGoal(goal, world.ball_radius_m, in, hit);
  for (const CircleShape& obstacle : world.obstacles) {
    hit = Min(hit, CircleEntry(in, obstacle.centre, obstacle.contact_radius_m));
  }
  const Lanes travelled = Min(hit, in.stop_m);
  RestLanes rest;
  rest.x = Select(in.moving, in.start_x + travelled * in.dir_x, in.start_x);
  rest.y = Select(in.moving, in.start_y + travelled * in.dir_y, in.start_y);
  const LaneMask path = PathCategory(world.lines, in, travelled, rest.x, rest.y);
  const LaneMask starts_inside = in.start_category == CategoryLanes(Category::kInfield);
  rest.category = Select(in.moving & starts_inside, path, in.start_category);
  return rest;
}

}  // namespace foresight
