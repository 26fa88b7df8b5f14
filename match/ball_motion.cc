#include "match/ball_motion.h"

#include <algorithm>
#include <cmath>

#include "planner/ray_cast.h"

namespace foresight {

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

std::optional<int> AdvanceRoll(BallRoll& roll, double dt_s, std::span<const BodyDisc> bodies) {
  const double a = roll.deceleration_mps2;
  const double t_stop = roll.speed0_mps / a;
  const double t = std::min(roll.elapsed_s + dt_s, t_stop);
  const double s_new = std::min(roll.length_m, roll.speed0_mps * t - 0.5 * a * t * t);
  roll.elapsed_s = t;
  const double advance_m = std::max(0.0, s_new - roll.travelled_m);
  const Vec2 here = roll.Position();
  double first_hit = advance_m;
  std::optional<int> hit_body;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].ignore) continue;
    const double s = RayCircleEntry(here, roll.dir_F, bodies[i].centre, bodies[i].contact_radius_m);
    if (s <= first_hit) {
      first_hit = s;
      hit_body = static_cast<int>(i);
    }
  }
  if (hit_body) {
    roll.travelled_m += first_hit;
    roll.length_m = roll.travelled_m;  // stopped dead against the body
  } else {
    roll.travelled_m = t >= t_stop ? roll.length_m : s_new;
  }
  return hit_body;
}

}  // namespace foresight
