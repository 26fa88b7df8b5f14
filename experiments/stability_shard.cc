#include "experiments/stability_shard.h"

namespace foresight {

int StabilityItems(const StabilityParams& params) {
  return MakeStabilityGrid(params.situation.field, params.grid_step_m, params.heading_step_rad)
      .PoseCount();
}

nlohmann::json StabilityShardResults(const StabilityResult& result, const Shard& shard) {
  const int poses = result.grid.PoseCount();
  const std::size_t counts = result.top_count.size() / static_cast<std::size_t>(poses);
  nlohmann::json items = nlohmann::json::array();
  for (int k = 0; k < shard.OwnedCount(poses); ++k) {
    const int pose = shard.Item(k);
    nlohmann::json top = nlohmann::json::array(), distinct = nlohmann::json::array();
    for (std::size_t c = 0; c < counts; ++c) {
      top.push_back(result.top_count[c * poses + pose]);
      distinct.push_back(result.distinct[c * poses + pose]);
    }
    items.push_back({{"pose", pose}, {"top", top}, {"distinct", distinct}});
  }
  return items;
}

StabilityResult MergeStabilityShards(const StabilityParams& params,
                                     const std::vector<ShardPart>& parts) {
  StabilityResult result = EmptyStabilityResult(params);
  const int poses = result.grid.PoseCount();
  const std::size_t counts = params.sample_counts.size();
  for (const ShardPart& part : parts) {
    const Shard& shard = part.header.shard;
    const ShardValue items = ResultsOf(part);
    for (int k = 0; k < shard.OwnedCount(poses); ++k) {
      const ShardValue item = items.At(k);
      const int pose = shard.Item(k);
      if (item["pose"].Int() != pose) item["pose"].Fail("must be " + std::to_string(pose));
      const ShardValue top = item["top"], distinct = item["distinct"];
      if (top.Size() != counts || distinct.Size() != counts)
        item.Fail("must have one entry per sample count (" + std::to_string(counts) + ")");
      for (std::size_t c = 0; c < counts; ++c) {
        const int t = top.At(c).Int(), n = distinct.At(c).Int();
        if (t < 1 || t > params.repeats || n < 1 || n > params.repeats - t + 1)
          top.At(c).Fail("not a count of " + std::to_string(params.repeats) + " decisions");
        result.top_count[c * poses + pose] = t;
        result.distinct[c * poses + pose] = n;
      }
    }
  }
  SummariseStability(params, result);
  return result;
}

}  // namespace foresight
