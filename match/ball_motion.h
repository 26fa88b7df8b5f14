// The ball in a match (Ros et al. 2009, sec. 5.2: "the ball's movement is modeled taking into
// account the friction with the field, starting with a high speed and decreasing through time").
//
// A kick's Outcome (match/kick_executor.h) gives the straight path from the launch point to the
// rest point p_F_rest, reached after time_s. The ball replays that path with the kick model's
// constant deceleration a: s(t) = v0 t - a t^2 / 2, where v0 = (d + a T^2 / 2) / T makes it cover
// the path's length d in exactly T (the coarse model's own launch speed when nothing stopped it,
// d = v0^2 / (2 a)). Posts and nets are inside the outcome already (the path ends at them). Robots
// move while the ball rolls, so each step the ball's advance is also tested against every robot
// body (a disc, or a capsule while a goalie blocks): the first body it meets ends this roll at the
// contact point, and that robot touched it. The match then rebounds it (ReboundOffBody).
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
  // The speed after travelling s metres: v^2 = v0^2 - 2 a s.
  double SpeedAt(double s_m) const;
};

// The roll that replays `outcome` from `p_F_start`; nullopt when the ball does not move.
std::optional<BallRoll> RollFromOutcome(const Vec2& p_F_start, const Outcome& outcome,
                                        double deceleration_mps2);

// A robot's body as the ball meets it: the points within contact_radius_m (body radius + ball
// radius) of the segment [a, b]; a == b for a standing robot (a disc).
struct BallBody {
  Vec2 a{0.0, 0.0};
  Vec2 b{0.0, 0.0};
  double contact_radius_m = 0.0;
  bool ignore = false;  // e.g. the kicker, which the ball leaves
};

struct BodyHit {
  int body = 0;
  Vec2 p_F_contact{0.0, 0.0};  // the ball's centre when it touches the body
  double speed_mps = 0.0;      // the ball's speed then
  double time_left_s = 0.0;    // of the step, after the contact
};

// Advances the roll by dt_s. When a body stops it, the roll ends at the contact point and the
// hit says where, how fast and how much of the step was left.
std::optional<BodyHit> AdvanceRoll(BallRoll& roll, double dt_s, std::span<const BallBody> bodies);

// The ball leaving a standing body it met at p_F_contact moving along unit dir_F (towards it):
// the coarse model's rebound (planner/first_hit.h, Reflect), reflected about the contact normal n
// (from the body's nearest axis point to the ball's centre) with its normal speed scaled by the
// restitution e, v' = v - (1 + e)(v . n) n. Returns the new unit direction and speed.
struct BallVelocity {
  Vec2 dir_F{1.0, 0.0};
  double speed_mps = 0.0;
};
BallVelocity ReboundOffBody(const BallBody& body, const Vec2& p_F_contact, const Vec2& dir_F,
                            double speed_mps, double restitution);

}  // namespace foresight
