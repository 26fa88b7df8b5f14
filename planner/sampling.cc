#include "planner/sampling.h"

#include <algorithm>
#include <cassert>

#include "common/random.h"
#include "planner/random_lanes.h"

namespace foresight {

DrawnSample DrawSample(const StateEstimate& estimate, std::uint64_t seed, std::uint64_t index) {
  DrawnSample sample;
  sample.stream = StreamKey(seed, index);
  const std::uint64_t key = sample.stream;
  Pose2& robot = sample.state.robot;
  robot.p_F.x() = estimate.robot.p_F.x() + estimate.sigma_robot_x_m * IndexedNormal(key, 0);
  robot.p_F.y() = estimate.robot.p_F.y() + estimate.sigma_robot_y_m * IndexedNormal(key, 1);
  robot.theta_rad =
      estimate.robot.theta_rad + estimate.sigma_robot_theta_rad * IndexedNormal(key, 2);
  // Normal 3 is the ball's y and 4 its x: the order of the sequential stream this replaced
  // (which drew y first), kept so that a sample without a slow-path normal keeps its numbers.
  const Vec2 p_R_ball(estimate.p_R_ball.x() + estimate.sigma_ball_x_m * IndexedNormal(key, 4),
                      estimate.p_R_ball.y() + estimate.sigma_ball_y_m * IndexedNormal(key, 3));
  sample.state.p_F_ball = robot.ToField(p_R_ball);
  sample.z_speed = IndexedNormal(key, 5);
  sample.z_direction = IndexedNormal(key, 6);
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

namespace {

// DrawSample's standard normals: robot x, y, heading, ball y, ball x, speed, direction.
constexpr int kSampleNormals = 7;

// SampleLanes from the drawn standard normals (`normal` in DrawSample's index order).
SampleLanes PlaceSampleLanes(const StateEstimate& estimate, LaneBits stream,
                             const Lanes (&normal)[kSampleNormals]) {
  SampleLanes s;
  s.stream = stream;
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

}  // namespace

void DrawSampleGroupsVector(const StateEstimate& estimate, std::uint64_t seed, std::uint64_t first,
                            int groups, SampleLanes* out) {
  assert(groups <= kDrawGroups);
  LaneBits stream[kDrawGroups];
  // Plain doubles, not Lanes: a missed normal is written through its address (Clang gives no
  // address of a vector's element).
  alignas(64) double normal[kDrawGroups][kSampleNormals][kLanes];
  LaneBits bits[kDrawGroups][kSampleNormals];
  // Bit k kLanes + l: normal k of lane l missed its rectangle (7 kLanes <= 56 bits).
  std::uint64_t misses[kDrawGroups];
  // The fast paths of every normal side by side, without a branch (no normal waits for another's
  // draws, and a miss, in about one lane group of five, is no misprediction) ...
  for (int g = 0; g < groups; ++g) {
    stream[g] = StreamKeyLanes(seed, first + static_cast<std::uint64_t>(g) * kLanes);
    misses[g] = 0;
    for (int k = 0; k < kSampleNormals; ++k) {
      LaneMask fast = BroadcastMask(-1);
      Store(IndexedNormalFastLanes(stream[g], static_cast<std::uint64_t>(k), &bits[g][k], fast),
            normal[g][k]);
      misses[g] |= static_cast<std::uint64_t>(MaskBits(~fast)) << (k * kLanes);
    }
  }
  MissedNormal missed[kDrawGroups * kLanes * kSampleNormals];
  int missed_count = 0;
  for (int g = 0; g < groups; ++g) {
    for (std::uint64_t m = misses[g]; m != 0; m &= m - 1) {
      const int i = __builtin_ctzll(m), k = i / kLanes, l = i % kLanes;
      missed[missed_count++] = {&normal[g][k][l], stream[g][l], static_cast<std::uint64_t>(k),
                                bits[g][k][l]};
    }
  }
  // ... then the misses of all groups together.
  if (missed_count > 0) FinishMissedNormals(missed, missed_count);
  for (int g = 0; g < groups; ++g) {
    Lanes z[kSampleNormals];
    for (int k = 0; k < kSampleNormals; ++k) z[k] = Load(normal[g][k]);
    out[g] = PlaceSampleLanes(estimate, stream[g], z);
  }
}

void DrawSampleGroupsScalar(const StateEstimate& estimate, std::uint64_t seed, std::uint64_t first,
                            int groups, SampleLanes* out) {
  for (int g = 0; g < groups; ++g) {
    out[g] = DrawSampleLanesScalar(estimate, seed, first + static_cast<std::uint64_t>(g) * kLanes);
  }
}

SampleLanes DrawSampleLanesVector(const StateEstimate& estimate, std::uint64_t seed,
                                  std::uint64_t first) {
  SampleLanes s;
  DrawSampleGroupsVector(estimate, seed, first, 1, &s);
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

void DrawSampleGroups(const StateEstimate& estimate, std::uint64_t seed, std::uint64_t first,
                      int groups, SampleLanes* out) {
  if constexpr (kDrawInLanes) {
    DrawSampleGroupsVector(estimate, seed, first, groups, out);
  } else {
    DrawSampleGroupsScalar(estimate, seed, first, groups, out);
  }
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
  SampleLanes drawn[kDrawGroups];
  for (int first = 0; first < count; first += kDrawGroups * kLanes) {
    const int groups = std::min(kDrawGroups, (count - first + kLanes - 1) / kLanes);
    DrawSampleGroups(estimate, seed, static_cast<std::uint64_t>(first), groups, drawn);
    for (int i = first; i < std::min(count, first + groups * kLanes); ++i) {
      const SampleLanes& s = drawn[(i - first) / kLanes];
      const int l = (i - first) % kLanes;
      DrawnSample& d = out[static_cast<std::size_t>(i)];
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
