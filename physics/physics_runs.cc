#include "physics/physics_runs.h"

#include <cmath>

#include "common/random.h"
#include "common/parallel_for.h"

namespace foresight {

std::vector<TrialResult> RunKickTrials(const PhysicsSimulator& simulator,
                                       const KickTrialsRequest& request) {
  std::vector<TrialResult> results(request.trials);
  ParallelFor(
      request.trials, request.threads,
      [&](int i) {
        ConcreteAction action;
        action.kick_index = request.kick_index;
        action.rotation_rad = request.rotation_rad;
        action.stream = StreamKey(request.seed, static_cast<std::uint64_t>(i), kPhysicsTrialDomain);
        results[i] = simulator.Run(request.state, action, request.record_trace);
      },
      request.progress);
  return results;
}

namespace {

double SampleSd(double sum, double sum_sq, int n) {
  if (n < 2) return 0.0;
  const double mean = sum / n;
  return std::sqrt(std::max(0.0, (sum_sq - n * mean * mean) / (n - 1)));
}

}  // namespace

TrialSummary Summarize(std::span<const TrialResult> results) {
  TrialSummary s;
  s.trials = static_cast<int>(results.size());
  Vec2 sum(0, 0), sum_sq(0, 0);
  double speed = 0.0, speed_sq = 0.0, cos_sum = 0.0, sin_sum = 0.0, time = 0.0;
  for (const TrialResult& r : results) {
    ++s.categories[static_cast<int>(r.outcome.category)];
    ++s.first_contacts[static_cast<int>(r.outcome.first_contact)];
    s.launched += r.launched;
    s.settled += r.settled;
    sum += r.outcome.p_F_rest;
    sum_sq += r.outcome.p_F_rest.cwiseProduct(r.outcome.p_F_rest);
    time += r.outcome.time_s;
    if (!r.touched) continue;
    ++s.touched;
    speed += r.launch_speed_mps;
    speed_sq += r.launch_speed_mps * r.launch_speed_mps;
    cos_sum += std::cos(r.launch_direction_rad);
    sin_sum += std::sin(r.launch_direction_rad);
  }
  if (s.trials == 0) return s;
  s.rest_mean_F = sum / s.trials;
  s.rest_sd_F =
      Vec2(SampleSd(sum.x(), sum_sq.x(), s.trials), SampleSd(sum.y(), sum_sq.y(), s.trials));
  s.time_mean_s = time / s.trials;
  if (s.touched > 0) {
    s.launch_speed_mean_mps = speed / s.touched;
    s.launch_speed_sd_mps = SampleSd(speed, speed_sq, s.touched);
    s.launch_direction_mean_rad = std::atan2(sin_sum, cos_sum);
    const double resultant = std::hypot(cos_sum, sin_sum) / s.touched;
    s.launch_direction_sd_rad = std::sqrt(-2.0 * std::log(std::max(resultant, 1e-300)));
  }
  return s;
}

}  // namespace foresight
