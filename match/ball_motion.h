// The ball in a match (Ros et al. 2009, sec. 5.2: "the ball's movement is modeled taking into
// account the friction with the field, starting with a high speed and decreasing through time").
//
// A kick's Outcome (match/kick_executor.h) gives the straight path from the launch point to the
// rest point p_F_rest, reached after time_s. The ball replays that path with the kick model's
// constant deceleration a: s(t) = v0 t - a t^2 / 2, where v0 = (d + a T^2 / 2) / T makes it cover
// the path's length d in exactly T (the coarse model's own launch speed when nothing stopped it,
// d = v0^2 / (2 a)). Posts and nets are inside the outcome already (the path ends at them). Robots
// move while the ball rolls, so each step the ball's advance is also tested against every robot
// body (a disc): the first body it meets stops it dead one ball radius short (fully inelastic,
// as the coarse model's obstacles), and that robot touched it.
#pragma once

#include <optional>
#include <span>

#include "common/geometry.h"
#include "models/outcome.h"

namespace foresight {

struct BallRoll {
  Vec2 p_F_start{0.0, 0.0};
  Vec2 dir_F{1.0, 0.0};
  double length_m = 0.0;  // path length d
  double speed0_mps = 0.0;
  double deceleration_mps2 = 0.0;
  double elapsed_s = 0.0;
  double travelled_m = 0.0;
  bool Done() const { return travelled_m >= length_m; }
  Vec2 Position() const { return p_F_start + travelled_m * dir_F; }
};

// The roll that replays `outcome` from `p_F_start`; nullopt when the ball does not move.
std::optional<BallRoll> RollFromOutcome(const Vec2& p_F_start, const Outcome& outcome,
                                        double deceleration_mps2);

struct BodyDisc {
  Vec2 centre{0.0, 0.0};
  double contact_radius_m = 0.0;  // body radius + ball radius
  bool ignore = false;            // e.g. the kicker, which the ball leaves
};

// Advances the roll by dt_s. Returns the index of the body that stopped it, if one did (the roll
// is then finished at the contact point).
std::optional<int> AdvanceRoll(BallRoll& roll, double dt_s, std::span<const BodyDisc> bodies);

}  // namespace foresight
