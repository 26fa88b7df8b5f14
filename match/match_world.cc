#include "match/match_world.h"

namespace foresight {

void StepBall(MatchWorld& world, double contact_m, double dt_s, double touch_tolerance_m) {
  MatchBall& ball = world.ball;
  if (ball.holder >= 0) {
    const Pose2& holder = world.robots[static_cast<std::size_t>(ball.holder)].pose;
    ball.p_F = holder.ToField(Vec2(contact_m, 0.0));
    return;
  }
  std::vector<BodyDisc> bodies;
  for (std::size_t i = 0; i < world.robots.size(); ++i) {
    bodies.push_back(
        {world.robots[i].pose.p_F, contact_m, static_cast<int>(i) == ball.leaving_kicker});
  }
  if (ball.roll) {
    AdvanceRoll(*ball.roll, dt_s, bodies);
    ball.p_F = ball.roll->Position();
    if (ball.roll->Done()) ball.roll.reset();
  }
  // A body that overlaps the ball (walked into it, or the ball rolled to rest in it) pushes it
  // out to its edge and stops it.
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].ignore) continue;
    const Vec2 away = ball.p_F - bodies[i].centre;
    const double distance = away.norm();
    if (distance >= contact_m) continue;
    const Vec2 dir =
        distance > 1e-9 ? Vec2(away / distance) : UnitVector(world.robots[i].pose.theta_rad);
    ball.p_F = bodies[i].centre + contact_m * dir;
    ball.roll.reset();
  }
  if (ball.leaving_kicker >= 0) {
    const Vec2& kicker = world.robots[static_cast<std::size_t>(ball.leaving_kicker)].pose.p_F;
    if ((ball.p_F - kicker).norm() > contact_m + touch_tolerance_m) ball.leaving_kicker = -1;
  }
}

}  // namespace foresight
