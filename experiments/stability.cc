#include "experiments/stability.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/checks.h"
#include "common/error.h"
#include "common/parallel_for.h"
#include "common/random.h"
#include "planner/coarse_planner.h"

namespace foresight {

namespace {

constexpr std::uint64_t kStabilityDomain = 0x73746162696c6974ULL;  // "stabilit"

// Centres of as many whole cells of `step` as fit into [-half, half], centred.
std::vector<double> CellCentres(double half, double step) {
  const int n = std::max(1, static_cast<int>(std::floor(2.0 * half / step + 1e-9)));
  const double first = -0.5 * (n - 1) * step;
  std::vector<double> centres;
  for (int i = 0; i < n; ++i) centres.push_back(first + i * step);
  return centres;
}

// The frequency of the most frequent key and the number of distinct keys among `keys`.
std::pair<int, int> TopAndDistinct(std::vector<int>& keys) {
  std::ranges::sort(keys);
  int top = 0, distinct = 0;
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i;
    while (j < keys.size() && keys[j] == keys[i]) ++j;
    top = std::max(top, static_cast<int>(j - i));
    ++distinct;
    i = j;
  }
  return {top, distinct};
}

StabilityCount Summarise(int samples, const int* top_count, const int* distinct, int poses,
                         int repeats) {
  StabilityCount count;
  count.samples = samples;
  long long above_80 = 0, above_50 = 0, at_most_20 = 0;
  double sum = 0.0, distinct_sum = 0.0;
  for (int p = 0; p < poses; ++p) {
    // Exact integer comparisons of top / R with 4/5, 1/2 and 1/5.
    const long long top = top_count[p];
    above_80 += 5 * top > 4LL * repeats;
    above_50 += 2 * top > repeats;
    at_most_20 += 5 * top <= repeats;
    sum += static_cast<double>(top) / repeats;
    distinct_sum += distinct[p];
  }
  count.share_above_80 = static_cast<double>(above_80) / poses;
  count.share_above_50 = static_cast<double>(above_50) / poses;
  count.share_at_most_20 = static_cast<double>(at_most_20) / poses;
  count.mean_top_share = sum / poses;
  count.mean_distinct = distinct_sum / poses;
  return count;
}

}  // namespace

Pose2 StabilityGrid::PoseAt(int pose) const {
  const std::size_t headings = headings_rad.size();
  return {positions_F[static_cast<std::size_t>(pose) / headings],
          headings_rad[static_cast<std::size_t>(pose) % headings]};
}

StabilityGrid MakeStabilityGrid(const FieldSpec& field, double step_m, double heading_step_rad) {
  StabilityGrid grid;
  grid.cell_size_m = step_m;
  for (double y : CellCentres(field.HalfWidth(), step_m)) {
    for (double x : CellCentres(field.HalfLength(), step_m)) grid.positions_F.emplace_back(x, y);
  }
  const int headings =
      std::max(1, static_cast<int>(std::ceil(2.0 * kPi / heading_step_rad - 1e-9)));
  for (int h = 0; h < headings; ++h) grid.headings_rad.push_back(WrapAngle(h * heading_step_rad));
  return grid;
}

int DecisionKey(int kick_index, double rotation_rad, double rotation_bin_rad) {
  constexpr int kBinsPerKick = 1 << 16;
  const int bins = std::max(1, static_cast<int>(std::lround(2.0 * kPi / rotation_bin_rad)));
  const int bin = static_cast<int>(std::lround(WrapAngle(rotation_rad) / rotation_bin_rad));
  return (kick_index + 1) * kBinsPerKick + ((bin % bins) + bins) % bins;
}

std::vector<double> StabilityResult::PositionMeans(int count_index) const {
  const int headings = static_cast<int>(grid.headings_rad.size());
  std::vector<double> means;
  for (std::size_t p = 0; p < grid.positions_F.size(); ++p) {
    double sum = 0.0;
    for (int h = 0; h < headings; ++h)
      sum += TopShare(count_index, static_cast<int>(p) * headings + h);
    means.push_back(sum / headings);
  }
  return means;
}

StabilityResult EmptyStabilityResult(const StabilityParams& params) {
  StabilityResult result;
  result.grid =
      MakeStabilityGrid(params.situation.field, params.grid_step_m, params.heading_step_rad);
  const std::size_t slots = params.sample_counts.size() * result.grid.PoseCount();
  result.repeats = params.repeats;
  result.top_count.assign(slots, 0);
  result.distinct.assign(slots, 0);
  result.decisions = static_cast<long long>(result.grid.PoseCount()) *
                     static_cast<long long>(params.sample_counts.size()) * params.repeats;
  return result;
}

void SummariseStability(const StabilityParams& params, StabilityResult& result) {
  const int poses = result.grid.PoseCount();
  result.counts.clear();
  for (std::size_t c = 0; c < params.sample_counts.size(); ++c) {
    const std::size_t offset = c * poses;
    result.counts.push_back(Summarise(params.sample_counts[c], result.top_count.data() + offset,
                                      result.distinct.data() + offset, poses, params.repeats));
  }
}

StabilityResult RunStability(const StabilityParams& params, std::uint64_t seed, int threads,
                             const std::function<void(int, int)>& progress, const Shard& shard) {
  StabilityResult result = EmptyStabilityResult(params);
  const int poses = result.grid.PoseCount();
  const int counts = static_cast<int>(params.sample_counts.size());
  const int repeats = params.repeats;

  // Every grid pose must be a valid situation (ball on the carpet): check before the work.
  Situation probe = params.situation;
  for (int p = 0; p < poses; ++p) {
    probe.state.robot = result.grid.PoseAt(p);
    const Pose2& pose = probe.state.robot;
    WithFile(params.file.string() + ": grid pose (" + FormatNumber(pose.p_F.x()) + ", " +
                 FormatNumber(pose.p_F.y()) + ", " + FormatNumber(pose.theta_rad * kRadToDeg) +
                 " deg)",
             [&] { probe.Validate(); });
  }
  const CoarsePlanner planner(params.situation);
  const int max_samples =
      *std::max_element(params.sample_counts.begin(), params.sample_counts.end());
  ParallelFor(
      shard.OwnedCount(poses), threads,
      [&](int owned) {
        const int pose = shard.Item(owned);
        StateEstimate state = params.situation.state;
        state.robot = result.grid.PoseAt(pose);
        const std::uint64_t pose_key =
            StreamKey(seed, static_cast<std::uint64_t>(pose), kStabilityDomain);
        std::vector<int> keys(static_cast<std::size_t>(repeats));
        // One evaluator and Decision per pose, redrawn for every decision (no allocation per
        // decision; the same bits as CoarsePlanner::Decide(state, ...), tested).
        CoarseActionEvaluator evaluator = planner.MakeEvaluator(state, max_samples, 0);
        Decision d;
        for (int c = 0; c < counts; ++c) {
          for (int r = 0; r < repeats; ++r) {
            const std::uint64_t decision =
                static_cast<std::uint64_t>(c) * static_cast<std::uint64_t>(repeats) +
                static_cast<std::uint64_t>(r);
            planner.Decide(state, params.strategy, params.sample_counts[c],
                           StreamKey(pose_key, decision), evaluator, d);
            keys[r] = DecisionKey(d.kick_index, d.rotation_rad, params.rotation_bin_rad);
          }
          const auto [top, n] = TopAndDistinct(keys);
          const std::size_t slot = static_cast<std::size_t>(c) * poses + pose;
          result.top_count[slot] = top;
          result.distinct[slot] = n;
        }
      },
      progress);
  if (shard.IsWhole()) SummariseStability(params, result);
  return result;
}

}  // namespace foresight
