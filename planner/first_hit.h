// The first static shape a rolling ball's straight path touches (posts, nets, obstacles), with
// what the rebounding roll needs to reflect the ball off it: every shape as a segment from `a`
// along unit `u` for length_m (a circle is a segment of length 0 at its centre), so the contact
// normal is the direction from the segment's nearest point to the ball's centre.
#pragma once

#include "planner/coarse_world.h"
#include "planner/ray_cast.h"

namespace foresight {

struct FirstHit {
  double s = kNoHit;  // path length to the contact, kNoHit when none
  Contact kind = Contact::kNone;
  Vec2 a{0.0, 0.0};
  Vec2 u{1.0, 0.0};
  double length_m = 0.0;

  // Keeps the candidate when it comes strictly first (earlier shapes win ties).
  void Offer(double candidate, Contact candidate_kind, const Vec2& shape_a, const Vec2& shape_u,
             double shape_length_m) {
    if (candidate < s) {
      s = candidate;
      kind = candidate_kind;
      a = shape_a;
      u = shape_u;
      length_m = shape_length_m;
    }
  }
};

// The first contact along start + s dir, 0 <= s, of the goals whose bounding circle the path
// [0, length_m] passes and of every obstacle (shapes in CoarseWorld's order).
FirstHit FindFirstHit(const CoarseWorld& world, const Vec2& start, const Vec2& dir,
                      double length_m);

// The ball's direction after touching `hit` at p_F_hit, moving along unit dir_F: reflected about
// the contact normal n with its normal component scaled by restitution e,
//   d' = d - (1 + e) (d . n) n,
// written component by component in the order planner/roll_lanes.cc repeats. `speed_factor` is
// |d'| (the speed after the contact over the speed before it); the direction is d' / |d'|.
struct Reflection {
  Vec2 dir_F{1.0, 0.0};
  double speed_factor = 0.0;
};
Reflection Reflect(const FirstHit& hit, const Vec2& p_F_hit, const Vec2& dir_F, double e);

}  // namespace foresight
