#include "planner/sampling.h"

#include "common/random.h"
#include "planner/random_lanes.h"

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

SampleLanes DrawSampleLanesScalar(const StateEstimate& estimate, std::uint64_t seed,
                                  std::uint64_t first) {
  SampleLanes s;
  for (int l = 0; l < kLanes; ++l) {
    const DrawnSample d = DrawSample(estimate, seed, first + static_cast<std::uint64_t>(l));
    s.stream[l] = d.stream;
    s.robot_x[l] = d.state.robot.p_F.x();
    s.robot_y[l] = d.state.robot.p_F.y();
    s.robot_theta_rad[l] = d.state.robot.theta_rad;
    s.ball_x[l] = d.state.p_F_ball.x();
    s.ball_y[l] = d.state.p_F_ball.y();
    s.z_speed[l] = d.z_speed;
    s.z_direction[l] = d.z_direction;
  }
  return s;
}

SampleLanes DrawSampleLanesVector(const StateEstimate& estimate, std::uint64_t seed,
                                  std::uint64_t first) {
  SampleLanes s;
  s.stream = StreamKeyLanes(seed, first);
  // DrawSample's draws in its order: robot x, y, heading, ball y, ball x, speed, direction.
  constexpr int kDraws = 7;
  Lanes normal[kDraws];
  LaneBits state = s.stream;
  LaneMask tail = BroadcastMask(0);
  std::uint64_t tail_state[kLanes];  // a tail lane's stream state before its first tail normal
  int tail_draw[kLanes];             // and that normal's place in the order
  for (int k = 0; k < kDraws; ++k) {
    const LaneBits before = state;
    const LaneMask tail_before = tail;
    normal[k] = NextNormalLanes(state, tail);
    if (__builtin_expect(Any(tail & ~tail_before), 0)) {
      for (int l = 0; l < kLanes; ++l) {
        if (tail[l] && !tail_before[l]) tail_state[l] = before[l], tail_draw[l] = k;
      }
    }
  }
  if (__builtin_expect(Any(tail), 0)) {
    // The tail normal and every later one of that sample from its scalar stream.
    for (int l = 0; l < kLanes; ++l) {
      if (!tail[l]) continue;
      RandomStream rng(tail_state[l]);
      for (int k = tail_draw[l]; k < kDraws; ++k) normal[k][l] = rng.NextNormal();
    }
  }
  s.robot_x = estimate.robot.p_F.x() + estimate.sigma_robot_x_m * normal[0];
  s.robot_y = estimate.robot.p_F.y() + estimate.sigma_robot_y_m * normal[1];
  s.robot_theta_rad = estimate.robot.theta_rad + estimate.sigma_robot_theta_rad * normal[2];
  const Lanes ball_R_x = estimate.p_R_ball.x() + estimate.sigma_ball_x_m * normal[4];
  const Lanes ball_R_y = estimate.p_R_ball.y() + estimate.sigma_ball_y_m * normal[3];
  // Pose2::ToField with SinCos's lanes.
  Lanes sin_theta, cos_theta;
  SinCosLanes(s.robot_theta_rad, &sin_theta, &cos_theta);
  s.ball_x = s.robot_x + (cos_theta * ball_R_x - sin_theta * ball_R_y);
  s.ball_y = s.robot_y + (sin_theta * ball_R_x + cos_theta * ball_R_y);
  s.z_speed = normal[5];
  s.z_direction = normal[6];
  return s;
}

// SSE2 alone has no 64-bit lane compares or blends, which the lanes' streams need: there the
// scalar draw per lane is faster (docs/PERFORMANCE.md), with the same bits.
#if defined(__SSE4_1__)
constexpr bool kDrawInLanes = true;
#else
constexpr bool kDrawInLanes = false;
#endif

SampleLanes DrawSampleLanes(const StateEstimate& estimate, std::uint64_t seed,
                            std::uint64_t first) {
  return kDrawInLanes ? DrawSampleLanesVector(estimate, seed, first)
                      : DrawSampleLanesScalar(estimate, seed, first);
}

void DrawSamples(const StateEstimate& estimate, std::uint64_t seed, int count,
                 std::vector<DrawnSample>& out) {
  out.resize(static_cast<std::size_t>(count));
  if constexpr (!kDrawInLanes) {  // scalar draws: no packing into lanes and out again
    for (int i = 0; i < count; ++i) {
      out[static_cast<std::size_t>(i)] = DrawSample(estimate, seed, static_cast<std::uint64_t>(i));
    }
    return;
  }
  for (int first = 0; first < count; first += kLanes) {
    const SampleLanes s = DrawSampleLanes(estimate, seed, static_cast<std::uint64_t>(first));
    for (int l = 0; l < kLanes && first + l < count; ++l) {
      DrawnSample& d = out[static_cast<std::size_t>(first + l)];
      d.stream = s.stream[l];
      d.state.robot.p_F = Vec2(s.robot_x[l], s.robot_y[l]);
      d.state.robot.theta_rad = s.robot_theta_rad[l];
      d.state.p_F_ball = Vec2(s.ball_x[l], s.ball_y[l]);
      d.z_speed = s.z_speed[l];
      d.z_direction = s.z_direction[l];
    }
  }
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
