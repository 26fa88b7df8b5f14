#include "planner/ball_roll.h"

#include <algorithm>
#include <cmath>

#include "planner/ray_cast.h"

namespace foresight {

namespace {

struct Hit {
  double s = kNoHit;
  Contact kind = Contact::kNone;
  void Offer(double candidate, Contact candidate_kind) {
    if (candidate < s) {
      s = candidate;
      kind = candidate_kind;
    }
  }
};

// Distance from `p` to the segment [a, a + length * dir].
double DistanceToPath(const Vec2& p, const Vec2& a, const Vec2& dir, double length) {
  const double along = std::clamp((p - a).dot(dir), 0.0, length);
  return (a + along * dir - p).norm();
}

void HitGoal(const GoalShapes& goal, double ball_radius, const Vec2& start, const Vec2& dir,
             double length, Hit& hit) {
  if (DistanceToPath(goal.bound_centre, start, dir, length) > goal.bound_radius_m) return;
  for (const CircleShape& post : goal.posts) {
    hit.Offer(RayCircleEntry(start, dir, post.centre, post.contact_radius_m), Contact::kPost);
  }
  for (const SegmentShape& net : goal.net) {
    hit.Offer(RayCapsuleEntry(start, dir, net.a, net.b, ball_radius), Contact::kNet);
  }
}

}  // namespace

Category ClassifyPosition(const CoarseWorld& world, const Vec2& p_F) {
  return ClassifyPosition(world.lines, p_F);
}

Outcome RollBall(const CoarseWorld& world, const Vec2& p_F_start, const Vec2& dir_F,
                 double speed_mps) {
  Outcome outcome;
  if (!(speed_mps > 0.0)) {
    outcome.p_F_rest = p_F_start;
    outcome.category = ClassifyPosition(world, p_F_start);
    return outcome;
  }
  const double a = world.deceleration_mps2;
  const double stop_m = StopDistance(speed_mps, a);
  Hit hit;
  for (const GoalShapes& goal : world.goals) {
    HitGoal(goal, world.ball_radius_m, p_F_start, dir_F, stop_m, hit);
  }
  for (const CircleShape& obstacle : world.obstacles) {
    hit.Offer(RayCircleEntry(p_F_start, dir_F, obstacle.centre, obstacle.contact_radius_m),
              Contact::kObstacle);
  }
  const double travelled_m = std::min(hit.s, stop_m);
  outcome.first_contact = hit.s <= stop_m ? hit.kind : Contact::kNone;
  outcome.p_F_rest = p_F_start + travelled_m * dir_F;
  outcome.category = ClassifyPath(world.lines, p_F_start, dir_F, travelled_m);
  // Time to cover travelled_m: solve travelled = v t - a t^2 / 2 for the first root.
  const double remaining_speed_sq = std::max(0.0, speed_mps * speed_mps - 2.0 * a * travelled_m);
  outcome.time_s = (speed_mps - std::sqrt(remaining_speed_sq)) / a;
  return outcome;
}

}  // namespace foresight
