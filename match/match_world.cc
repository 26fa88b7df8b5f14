#include "match/match_world.h"

#include "planner/ball_roll.h"

namespace foresight {

BallBody BodyOf(const RobotState& robot, double contact_m) {
  const double half_axis_m = robot.block_half_span_m - contact_m;
  if (!(half_axis_m > 0.0)) return {robot.pose.p_F, robot.pose.p_F, contact_m, false};
  const Vec2 across = UnitVector(robot.pose.theta_rad + 0.5 * kPi);
  return {robot.pose.p_F - half_axis_m * across, robot.pose.p_F + half_axis_m * across, contact_m,
          false};
}

namespace {

// The rolling ball's step: advance, rebound off the bodies it meets, roll on.
void RollBallStep(MatchWorld& world, const BallStepParams& params, std::vector<BallBody>& bodies,
                  std::vector<int>& met) {
  MatchBall& ball = world.ball;
  double left_s = params.dt_s;
  for (int contacts = 0; ball.roll; ++contacts) {
    const std::optional<BodyHit> hit = AdvanceRoll(*ball.roll, left_s, bodies);
    ball.p_F = ball.roll->Position();
    if (!hit) break;
    met.push_back(hit->body);
    if (contacts + 1 >= kMaxBodyContactsPerStep) {
      ball.roll.reset();
      break;
    }
    // Whatever the ball meets, the kicker is a body again from now on (a ball sent back
    // towards it must not pass through it).
    if (ball.leaving_kicker >= 0) bodies[static_cast<std::size_t>(ball.leaving_kicker)].ignore = false;
    ball.leaving_kicker = -1;
    const BallVelocity after =
        ReboundOffBody(bodies[static_cast<std::size_t>(hit->body)], hit->p_F_contact,
                       ball.roll->dir_F, hit->speed_mps, params.robot_restitution);
    const Outcome roll_on = RollBall(*params.field, hit->p_F_contact, after.dir_F, after.speed_mps);
    ball.roll = RollFromOutcome(hit->p_F_contact, roll_on, ball.roll->deceleration_mps2);
    left_s = hit->time_left_s;
  }
  if (ball.roll && ball.roll->Done()) ball.roll.reset();
}

}  // namespace

std::vector<int> StepBall(MatchWorld& world, const BallStepParams& params) {
  MatchBall& ball = world.ball;
  std::vector<int> met;
  if (ball.holder >= 0) {
    const Pose2& holder = world.robots[static_cast<std::size_t>(ball.holder)].pose;
    ball.p_F = holder.ToField(Vec2(params.contact_m, 0.0));
    return met;
  }
  std::vector<BallBody> bodies;
  for (std::size_t i = 0; i < world.robots.size(); ++i) {
    bodies.push_back(BodyOf(world.robots[i], params.contact_m));
    bodies.back().ignore = static_cast<int>(i) == ball.leaving_kicker;
  }
  if (ball.roll) RollBallStep(world, params, bodies, met);
  // A body that overlaps the ball (walked into it, or the ball rolled to rest in it) pushes it
  // out to its edge and stops it.
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].ignore) continue;
    const Vec2 away = ball.p_F - bodies[i].a;
    const double distance = away.norm();
    if (distance >= params.contact_m || bodies[i].a != bodies[i].b) continue;
    const Vec2 dir =
        distance > 1e-9 ? Vec2(away / distance) : UnitVector(world.robots[i].pose.theta_rad);
    ball.p_F = bodies[i].a + params.contact_m * dir;
    ball.roll.reset();
  }
  if (ball.leaving_kicker >= 0) {
    const Vec2& kicker = world.robots[static_cast<std::size_t>(ball.leaving_kicker)].pose.p_F;
    if ((ball.p_F - kicker).norm() > params.contact_m + params.touch_tolerance_m) {
      ball.leaving_kicker = -1;
    }
  }
  return met;
}

}  // namespace foresight
