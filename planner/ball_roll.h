// The coarse ball model (Mellmann & Schlotter, sec. III-C; NaoTH's rolling-friction model):
// after the launch the ball moves along a straight line with constant deceleration a = mu * g,
//   s(t) = v0 t - a t^2 / 2,  at rest after d = v0^2 / (2 a) at t = v0 / a.
// A kick's launch offset L (models/kick_model.h, 0 in the paper's models) moves where free rolling
// starts: the ball covers L at v0 first (it slides there in physics), so it rests L + d away.
// Static objects stop it fully inelastically (the paper's model): the path ends where the ball
// first touches a goal post, a net or an obstacle (its centre one radius short of the surface).
// With the world's rebounds on it rebounds instead (planner/first_hit.h: reflected
// about the contact normal, its normal speed scaled by the pair's restitution) and rolls on from
// there at the speed it had left, until it rests or touches a shape after max_contacts rebounds.
// The first field line the path crosses outward decides the category: a goal line between the
// posts is a goal, any other line is out. A ball that starts out or in a goal keeps that category.
#pragma once

#include <algorithm>
#include <cmath>

#include "planner/coarse_world.h"

namespace foresight {

// Rolls a ball from p_F_start in unit direction dir_F at speed_mps (<= 0: it stays), free
// rolling starting launch_offset_m (>= 0) along the path.
Outcome RollBall(const CoarseWorld& world, const Vec2& p_F_start, const Vec2& dir_F,
                 double speed_mps, double launch_offset_m = 0.0);

// Category of a ball resting at p_F that crossed no line on its way (e.g. it started outside).
Category ClassifyPosition(const CoarseWorld& world, const Vec2& p_F);

// Distance the ball travels before resting on open carpet: v^2 / (2 a).
inline double StopDistance(double speed_mps, double deceleration_mps2) {
  return speed_mps * speed_mps / (2.0 * deceleration_mps2);
}

// Speed after rolling rolled_m from speed_mps: v^2 = v0^2 - 2 a s (0 once at rest).
inline double SpeedAfterRolling(double speed_mps, double deceleration_mps2, double rolled_m) {
  return std::sqrt(std::max(0.0, speed_mps * speed_mps - 2.0 * deceleration_mps2 * rolled_m));
}

// Time to roll rolled_m from speed_mps (the first root of s = v0 t - a t^2 / 2); at most the time
// to rest, v0 / a, when the ball rests before rolled_m.
inline double TimeToRoll(double speed_mps, double deceleration_mps2, double rolled_m) {
  return (speed_mps - SpeedAfterRolling(speed_mps, deceleration_mps2, rolled_m)) /
         deceleration_mps2;
}

}  // namespace foresight
