#include "planner/ball_roll.h"

#include <algorithm>
#include <cmath>

#include "planner/first_hit.h"

namespace foresight {

namespace {

// Speed after `travelled_m` of a leg launched at speed_mps whose free roll starts offset_m along
// it (the same operations as planner/roll_lanes.cc).
double SpeedAfter(double speed_mps, double a, double offset_m, double travelled_m) {
  return SpeedAfterRolling(speed_mps, a, std::max(0.0, travelled_m - offset_m));
}

// Time to cover travelled_m of such a leg: the offset at the launch speed, then the roll
// (solve rolled = v t - a t^2 / 2 for the first root).
double LegTime(double speed_mps, double a, double offset_m, double travelled_m) {
  return std::min(travelled_m, offset_m) / speed_mps +
         (speed_mps - SpeedAfter(speed_mps, a, offset_m, travelled_m)) / a;
}

// The paper's model: the first contact ends the roll.
Outcome RollInelastic(const CoarseWorld& world, const Vec2& start, const Vec2& dir,
                      double speed_mps, double offset_m) {
  const double a = world.deceleration_mps2;
  const double stop_m = StopDistance(speed_mps, a) + offset_m;
  const FirstHit hit = FindFirstHit(world, start, dir, stop_m);
  const double travelled_m = std::min(hit.s, stop_m);
  Outcome outcome;
  outcome.first_contact = hit.s <= stop_m ? hit.kind : Contact::kNone;
  outcome.p_F_rest = start + travelled_m * dir;
  outcome.category = ClassifyPath(world.lines, start, dir, travelled_m);
  outcome.time_s = LegTime(speed_mps, a, offset_m, travelled_m);
  return outcome;
}

// Leg after leg: a contact within the leg reflects the ball and starts the next one there.
// The category is the first leg's that crosses a line (every leg before it ended infield).
Outcome RollRebounding(const CoarseWorld& world, const Vec2& start, const Vec2& dir,
                       double speed_mps, double offset_m) {
  const double a = world.deceleration_mps2;
  Outcome outcome;
  bool decided = false;
  Vec2 p = start, d = dir;
  double v = speed_mps, offset = offset_m;
  double stop_m = StopDistance(v, a) + offset;
  for (int leg = 0;; ++leg) {
    const FirstHit hit = FindFirstHit(world, p, d, stop_m);
    const double travelled_m = std::min(hit.s, stop_m);
    const Vec2 end = p + travelled_m * d;
    const Category category = ClassifyPath(world.lines, p, d, travelled_m);
    if (!decided && category != Category::kInfield) {
      outcome.category = category;
      decided = true;
    }
    if (leg == 0) outcome.first_contact = hit.s <= stop_m ? hit.kind : Contact::kNone;
    outcome.time_s += LegTime(v, a, offset, travelled_m);
    outcome.p_F_rest = end;
    if (!(hit.s <= stop_m) || leg == world.rebounds.max_contacts) break;
    const Reflection r = Reflect(hit, end, d, world.RestitutionOf(hit.kind));
    const double v_after = SpeedAfter(v, a, offset, travelled_m) * r.speed_factor;
    if (!(v_after > 0.0)) break;  // a head-on contact with e = 0 stops it there
    p = end;
    d = r.dir_F;
    v = v_after;
    offset = 0.0;
    stop_m = StopDistance(v, a);
  }
  return outcome;
}

}  // namespace

Category ClassifyPosition(const CoarseWorld& world, const Vec2& p_F) {
  return ClassifyPosition(world.lines, p_F);
}

Outcome RollBall(const CoarseWorld& world, const Vec2& p_F_start, const Vec2& dir_F,
                 double speed_mps, double launch_offset_m) {
  if (!(speed_mps > 0.0)) {
    Outcome outcome;
    outcome.p_F_rest = p_F_start;
    outcome.category = ClassifyPosition(world, p_F_start);
    return outcome;
  }
  return world.rebounds.enabled
             ? RollRebounding(world, p_F_start, dir_F, speed_mps, launch_offset_m)
             : RollInelastic(world, p_F_start, dir_F, speed_mps, launch_offset_m);
}

}  // namespace foresight
