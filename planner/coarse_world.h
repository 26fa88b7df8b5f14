// The static world of the coarse model, precomputed once per scene: goal posts and obstacles as
// circles, nets as segments, and the lines whose crossing puts the ball out or into a goal.
//
// The lines that decide the category are models/field_lines.h. Goals: posts at
// (+-post_centre_x, +-post_centre_y); each net is three segments from the posts back
// net_depth_m (two sides and the back), of zero thickness.
#pragma once

#include <array>
#include <vector>

#include "models/field_lines.h"
#include "models/outcome.h"

namespace foresight {

struct CircleShape {
  Vec2 centre{0.0, 0.0};
  double contact_radius_m = 0.0;  // shape radius plus ball radius: where the ball centre stops
  Contact kind = Contact::kNone;
};

struct SegmentShape {
  Vec2 a{0.0, 0.0};
  Vec2 b{0.0, 0.0};
  // Derived once, as RayCapsuleEntry derives them (planner/roll_lanes.h needs the same bits).
  double length_m = 0.0;
  Vec2 u{1.0, 0.0};       // unit axis a -> b
  Vec2 normal{0.0, 1.0};  // u turned by +90 deg

  static SegmentShape Between(const Vec2& a, const Vec2& b);
};

struct GoalShapes {
  std::array<CircleShape, 2> posts;
  std::array<SegmentShape, 3> net;  // left side, back, right side
  Vec2 bound_centre{0.0, 0.0};      // a circle containing posts and net, grown by the ball
  double bound_radius_m = 0.0;
  // The largest squared distance d2 whose correctly rounded square root is <= bound_radius_m
  // (SquaredBound): sqrt(d2) > bound_radius_m exactly when d2 > bound_distance_sq_max, so lanes
  // test the bound without a square root and with the same result.
  double bound_distance_sq_max = 0.0;
};

// The largest double d with RN(sqrt(d)) <= r, for r >= 0 (RN: IEEE's correctly rounded square
// root, which is monotone, so d2 > it holds exactly when RN(sqrt(d2)) > r).
double SquaredBound(double r);

struct CoarseWorld {
  double ball_radius_m = 0.0;
  double deceleration_mps2 = 0.0;
  FieldLines lines;
  std::array<GoalShapes, 2> goals;  // [0] opponent (+x), [1] own (-x)
  std::vector<CircleShape> obstacles;
  CoarseRebounds rebounds;  // off: the paper's inelastic stop (planner/ball_roll.h)

  // The restitution of a contact of this kind (rebounds on).
  double RestitutionOf(Contact kind) const {
    return kind == Contact::kPost ? rebounds.post
                                  : (kind == Contact::kNet ? rebounds.net : rebounds.robot);
  }

  static CoarseWorld Build(const Scene& scene);
};

}  // namespace foresight
