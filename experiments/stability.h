// Decision stability against the number of samples (Mellmann & Schlotter, sec. V-A, Fig. 4).
//
// Robot poses on a grid over the field: the centres of square cells of grid_step_m that tile
// the field between its lines, each with headings 0, h, 2h, ... below 360 deg; the ball lies at
// the robot's feet (the situation's ball offset and belief sigmas). For each pose and each
// sample count N the decision is made R times with independent seeds. Two decisions are the
// same when they take the same kick (or none) with turns in the same rotation bin (bins of
// rotation_bin centred on 0). A pose's top share is the frequency of its most frequent decision
// ("the highest column of the decision histogram"). Per N the experiment reports the share of
// poses whose top share is > 0.8, > 0.5 and <= 0.2.
//
// Decision r of pose p at count index c draws from StreamKey(StreamKey(seed, p, domain),
// c R + r): results do not depend on the thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "common/geometry.h"
#include "common/shard.h"
#include "experiments/experiment_params.h"

namespace foresight {

struct StabilityGrid {
  std::vector<Vec2> positions_F;     // cell centres, row by row (y, then x ascending)
  std::vector<double> headings_rad;  // 0, step, ...
  double cell_size_m = 0.0;

  int PoseCount() const { return static_cast<int>(positions_F.size() * headings_rad.size()); }
  // Pose p is position p / headings, heading p % headings.
  Pose2 PoseAt(int pose) const;
};

// Cells of `step_m` tiling [-L/2, L/2] x [-W/2, W/2] (as many whole cells as fit, centred).
StabilityGrid MakeStabilityGrid(const FieldSpec& field, double step_m, double heading_step_rad);

struct StabilityCount {
  int samples = 0;
  double share_above_80 = 0.0;    // poses whose most frequent decision has > 80 %
  double share_above_50 = 0.0;    // ... > 50 %
  double share_at_most_20 = 0.0;  // ... <= 20 %
  double mean_top_share = 0.0;
  double mean_distinct = 0.0;  // distinct decisions per pose, mean
};

struct StabilityResult {
  StabilityGrid grid;
  std::vector<StabilityCount> counts;  // one per sample count, in the params' order
  int repeats = 0;
  // How often the most frequent decision of every pose was made, per sample count:
  // [count_index * PoseCount() + pose], out of `repeats`.
  std::vector<int> top_count;
  std::vector<int> distinct;  // distinct decisions, indexed like top_count
  long long decisions = 0;

  double TopShare(int count_index, int pose) const {
    return static_cast<double>(top_count[static_cast<std::size_t>(count_index) * grid.PoseCount() +
                                         static_cast<std::size_t>(pose)]) /
           repeats;
  }

  // Per position, the mean top share over its headings at count index c.
  std::vector<double> PositionMeans(int count_index) const;
};

// The (kick, rotation bin) key of a decision; kick_index -1 (none) is a key of its own. Bins are
// centred on 0 and wrap around: turns of +179 and -179 deg share the bin of 180 deg.
int DecisionKey(int kick_index, double rotation_rad, double rotation_bin_rad);

// `progress(done, total)` counts poses. Throws InputError if a grid pose puts the ball off the
// carpet (it cannot with the shipped fields and ball offsets). With a shard other than the whole
// run, only the shard's poses are decided (the others stay 0) and `counts` stays empty:
// experiments/stability_shard.h merges the shards and SummariseStability completes the result.
StabilityResult RunStability(const StabilityParams& params, std::uint64_t seed, int threads,
                             const std::function<void(int, int)>& progress = {},
                             const Shard& shard = {});

// The grid, the empty per-pose tables and the decision count of a run of `params`.
StabilityResult EmptyStabilityResult(const StabilityParams& params);
// `counts` from every pose's top_count and distinct.
void SummariseStability(const StabilityParams& params, StabilityResult& result);

}  // namespace foresight
