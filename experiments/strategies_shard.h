// The strategies experiment in shards: a shard's starts as the results of its shard
// file (report/shard_file.h), and the whole result again from all shards. An item is a start;
// its result is every strategy's run from it (and, for the example start, the runs' steps),
// numbers written exactly, so the merged report has the bytes of an unsharded run.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "experiments/strategies.h"
#include "report/shard_file.h"

namespace foresight {

// The results of `shard`'s starts in `result` (a run with that shard), in start order.
nlohmann::json StrategiesShardResults(const StrategiesParams& params,
                                      const StrategiesResult& result, const Shard& shard);

// The whole run's result from its shards (ReadShardParts' order): the same as an unsharded
// RunStrategies with `seed`. InputError when a result is malformed.
StrategiesResult MergeStrategiesShards(const StrategiesParams& params, std::uint64_t seed,
                                       const std::vector<ShardPart>& parts);

}  // namespace foresight
