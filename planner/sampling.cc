#include "planner/sampling.h"

#include "common/random.h"

namespace foresight {

DrawnSample DrawSample(const StateEstimate& estimate, std::uint64_t seed, std::uint64_t index) {
  DrawnSample sample;
  sample.stream = StreamKey(seed, index);
  RandomStream rng(sample.stream);
  Pose2& robot = sample.state.robot;
  robot.p_F.x() = estimate.robot.p_F.x() + estimate.sigma_robot_x_m * rng.NextNormal();
  robot.p_F.y() = estimate.robot.p_F.y() + estimate.sigma_robot_y_m * rng.NextNormal();
  robot.theta_rad = estimate.robot.theta_rad + estimate.sigma_robot_theta_rad * rng.NextNormal();
  // y before x, in two statements: the order of a constructor's arguments is unspecified, and
  // y first is the order GCC gave the one expression this was before, so results recorded with
  // GCC builds keep their bytes and every compiler now draws alike.
  const double ball_noise_y = rng.NextNormal();
  const double ball_noise_x = rng.NextNormal();
  const Vec2 p_R_ball(estimate.p_R_ball.x() + estimate.sigma_ball_x_m * ball_noise_x,
                      estimate.p_R_ball.y() + estimate.sigma_ball_y_m * ball_noise_y);
  sample.state.p_F_ball = robot.ToField(p_R_ball);
  sample.z_speed = rng.NextNormal();
  sample.z_direction = rng.NextNormal();
  return sample;
}

void DrawSamples(const StateEstimate& estimate, std::uint64_t seed, int count,
                 std::vector<DrawnSample>& out) {
  out.resize(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i)
    out[i] = DrawSample(estimate, seed, static_cast<std::uint64_t>(i));
}

ConcreteAction MakeAction(const KickModel& kicks, int kick_index, double rotation_rad,
                          const DrawnSample& sample) {
  ConcreteAction action;
  action.kick_index = kick_index;
  action.rotation_rad = rotation_rad;
  // A key of its own: the sample's stream already drew the state and the kick noise, and a
  // simulator that draws more (physics) must not repeat those numbers.
  action.stream = StreamKey(sample.stream, 0, kActionStreamDomain);
  if (kick_index != kNoKick) {
    const KickSpec& kick = kicks.kicks[static_cast<std::size_t>(kick_index)];
    action.launch_speed_mps = LaunchSpeed(kick, sample.z_speed);
    action.launch_direction_rad = LaunchDirection(kick, sample.z_direction);
    action.launch_offset_m = kick.launch_offset_m;
  }
  return action;
}

}  // namespace foresight
