#include "match/ball_motion.h"

#include <algorithm>
#include <cmath>

#include "planner/ball_roll.h"
#include "planner/first_hit.h"
#include "planner/ray_cast.h"

namespace foresight {

double BallRoll::SpeedAt(double s_m) const {
  return SpeedAfterRolling(speed0_mps, deceleration_mps2, s_m);
}

std::optional<BallRoll> RollFromOutcome(const Vec2& p_F_start, const Outcome& outcome,
                                        double deceleration_mps2) {
  const Vec2 path = outcome.p_F_rest - p_F_start;
  const double d = path.norm();
  if (!(d > 1e-9) || !(outcome.time_s > 0.0)) return std::nullopt;
  BallRoll roll;
  roll.p_F_start = p_F_start;
  roll.dir_F = path / d;
  roll.length_m = d;
  roll.deceleration_mps2 = deceleration_mps2;
  const double t = outcome.time_s;
  roll.speed0_mps = (d + 0.5 * deceleration_mps2 * t * t) / t;
  return roll;
}

std::optional<BodyHit> AdvanceRoll(BallRoll& roll, double dt_s, std::span<const BallBody> bodies) {
  const double a = roll.deceleration_mps2;
  const double t_stop = roll.speed0_mps / a;
  const double t = std::min(roll.elapsed_s + dt_s, t_stop);
  const double s_new = std::min(roll.length_m, roll.speed0_mps * t - 0.5 * a * t * t);
  const double advance_m = std::max(0.0, s_new - roll.travelled_m);
  const Vec2 here = roll.Position();
  double first_hit = advance_m;
  std::optional<int> hit_body;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].ignore) continue;
    const double s =
        RayCapsuleEntry(here, roll.dir_F, bodies[i].a, bodies[i].b, bodies[i].contact_radius_m);
    if (s <= first_hit) {
      first_hit = s;
      hit_body = static_cast<int>(i);
    }
  }
  if (!hit_body) {
    roll.elapsed_s = t;
    roll.travelled_m = t >= t_stop ? roll.length_m : s_new;
    return std::nullopt;
  }
  const double s_hit = roll.travelled_m + first_hit;
  const double speed = roll.SpeedAt(s_hit);
  const double t_hit = std::min(TimeToRoll(roll.speed0_mps, a, s_hit), t);
  const double step_end_s = roll.elapsed_s + dt_s;
  roll.travelled_m = s_hit;
  roll.length_m = s_hit;  // this roll ends at the body
  roll.elapsed_s = t_hit;
  return BodyHit{*hit_body, roll.Position(), speed, std::max(0.0, step_end_s - t_hit)};
}

BallVelocity ReboundOffBody(const BallBody& body, const Vec2& p_F_contact, const Vec2& dir_F,
                            double speed_mps, double restitution) {
  // The body as the coarse model's contact shape: a segment from a along u (length 0: a disc).
  FirstHit shape;
  shape.kind = Contact::kRobot;
  shape.a = body.a;
  shape.length_m = (body.b - body.a).norm();
  if (shape.length_m > 0.0) shape.u = (body.b - body.a) / shape.length_m;
  const Reflection r = Reflect(shape, p_F_contact, dir_F, restitution);
  return {r.dir_F, speed_mps * r.speed_factor};
}

}  // namespace foresight
