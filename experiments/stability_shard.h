// The stability experiment in shards: a shard's poses as the results of its shard
// file (report/shard_file.h), and the whole result again from all shards. An item is a pose;
// its result is, per sample count, the frequency of its most frequent decision and the number
// of distinct decisions: integers, so the merge is exact.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "experiments/stability.h"
#include "report/shard_file.h"

namespace foresight {

// The run's item count: its poses.
int StabilityItems(const StabilityParams& params);

// The results of `shard`'s poses in `result` (a run with that shard), in pose order.
nlohmann::json StabilityShardResults(const StabilityResult& result, const Shard& shard);

// The whole run's result from its shards (ReadShardParts' order), summarised: the same as an
// unsharded RunStability. InputError when a result is malformed.
StabilityResult MergeStabilityShards(const StabilityParams& params,
                                     const std::vector<ShardPart>& parts);

}  // namespace foresight
