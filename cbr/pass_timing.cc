#include "cbr/pass_timing.h"

#include <algorithm>
#include <cmath>

#include "common/random.h"

namespace foresight {

namespace {

constexpr std::uint64_t kPassSampleKey = 0x7061'7373'74696dULL;  // "passtim"

double OpponentTime(const Vec2& ball_F, const Vec2& opponent_F, const PassTimingParams& p) {
  return p.reaction_s + std::max(0.0, (ball_F - opponent_F).norm() - p.reach_m) / p.opponent_speed_mps;
}

// Whether any opponent gets to the ball of one sampled pass before the receiver has it.
bool Intercepted(const FuzzyTrajectory& t, double speed_mps, double heading_rad,
                 double decel_mps2, std::span<const Vec2> opponents_F,
                 const PassTimingParams& p) {
  const Vec2 dir(std::cos(heading_rad), std::sin(heading_rad));
  const double to_receiver_m = std::max(0.0, t.length_m - p.reach_m);
  const double rest_m = speed_mps * speed_mps / (2.0 * decel_mps2);
  double end_s;  // when the receiver has the ball
  Vec2 rest_F = t.start_F + dir * std::min(rest_m, to_receiver_m);
  if (rest_m >= to_receiver_m) {
    const double disc = speed_mps * speed_mps - 2.0 * decel_mps2 * to_receiver_m;
    end_s = (speed_mps - std::sqrt(std::max(0.0, disc))) / decel_mps2;
  } else {
    const double walk_s = std::max(0.0, (rest_F - t.end_F).norm() - p.reach_m) / p.receiver_speed_mps;
    end_s = std::max(speed_mps / decel_mps2, walk_s);
  }
  for (double time = 0.0;; time += p.time_step_s) {
    const double tt = std::min(time, end_s);
    const double moving_s = std::min(tt, speed_mps / decel_mps2);
    const Vec2 ball = t.start_F + dir * std::min(speed_mps * moving_s - 0.5 * decel_mps2 * moving_s * moving_s, rest_m);
    for (const Vec2& o : opponents_F) {
      if (OpponentTime(ball, o, p) <= tt) return true;
    }
    if (tt >= end_s) return false;
  }
}

}  // namespace

void DrawPassSamples(int samples, PassTimingParams* params) {
  params->z.clear();
  RandomStream stream(StreamKey(kPassSampleKey, 0));
  for (int i = 0; i < samples; ++i) {
    const double speed_z = stream.NextNormal();
    params->z.emplace_back(speed_z, stream.NextNormal());
  }
}

double PassSuccess(const CaseBallPath& path, std::span<const Vec2> opponents_F,
                   const KickModel& kicks, const PassTimingParams& params) {
  double success = 1.0;
  for (const FuzzyTrajectory& t : path.View()) {
    if (t.action != ActionType::kPass || t.kick == nullptr || params.z.empty()) continue;
    const auto index = kicks.Find(t.kick->kick);
    if (!index) continue;
    const KickSpec& k = kicks.kicks[static_cast<std::size_t>(*index)];
    const double aim = std::atan2(t.u.y(), t.u.x());
    int free = 0;
    for (const auto& [zv, za] : params.z) {
      const double v = std::max(0.0, k.speed_mps + k.sigma_speed_mps * zv);
      free += !Intercepted(t, v, aim + k.sigma_direction_rad * za,
                           kicks.rolling_deceleration_mps2, opponents_F, params);
    }
    success *= static_cast<double>(free) / static_cast<double>(params.z.size());
  }
  return success;
}

}  // namespace foresight
