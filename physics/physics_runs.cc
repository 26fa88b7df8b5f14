#include "physics/physics_runs.h"

#include <algorithm>
#include <cmath>

#include "common/parallel_for.h"
#include "common/random.h"
#include "stats/statistics.h"

namespace foresight {

std::vector<TrialResult> RunKickTrials(const PhysicsSimulator& simulator,
                                       const KickTrialsRequest& request) {
  const int owned = request.shard.OwnedCount(request.trials);
  std::vector<TrialResult> results(static_cast<std::size_t>(owned));
  ParallelFor(
      owned, request.threads,
      [&](int k) {
        const int i = request.shard.Item(k);
        ConcreteAction action;
        action.kick_index = request.kick_index;
        action.rotation_rad = request.rotation_rad;
        action.stream = StreamKey(request.seed, static_cast<std::uint64_t>(i), kPhysicsTrialDomain);
        results[k] = simulator.Run(request.state, action, request.record_trace,
                                      request.scene_rate_hz);
      },
      request.progress);
  return results;
}

TrialSummary Summarize(std::span<const TrialResult> results) {
  TrialSummary s;
  s.trials = static_cast<int>(results.size());
  std::vector<double> rest_x, rest_y, times, speeds, directions;
  for (const TrialResult& r : results) {
    ++s.categories[static_cast<int>(r.outcome.category)];
    ++s.first_contacts[static_cast<int>(r.outcome.first_contact)];
    s.launched += r.launched;
    s.settled += r.settled;
    s.fell += r.fell;
    s.blocked += r.blocked;
    s.max_tilt_rad = std::max(s.max_tilt_rad, r.max_tilt_rad);
    s.placement_redrawn += r.draw.placement_redraws > 0;
    s.placement_redraws += r.draw.placement_redraws;
    rest_x.push_back(r.outcome.p_F_rest.x());
    rest_y.push_back(r.outcome.p_F_rest.y());
    times.push_back(r.outcome.time_s);
    if (!r.touched) continue;
    ++s.touched;
    speeds.push_back(r.launch_speed_mps);
    directions.push_back(r.launch_direction_rad);
  }
  // The statistics' own mean, two-pass sd and circular summary (stats/statistics.h).
  const MeanSd x = SampleMeanSd(rest_x), y = SampleMeanSd(rest_y), speed = SampleMeanSd(speeds);
  s.rest_mean_F = Vec2(x.mean, y.mean);
  s.rest_sd_F = Vec2(x.sd, y.sd);
  s.time_mean_s = SampleMeanSd(times).mean;
  s.launch_speed_mean_mps = speed.mean;
  s.launch_speed_sd_mps = speed.sd;
  const CircularSummary direction = SummarizeCircular(directions);
  s.launch_direction_mean_rad = direction.mean_rad;
  s.launch_direction_sd_rad = direction.sd_rad;
  return s;
}

}  // namespace foresight
