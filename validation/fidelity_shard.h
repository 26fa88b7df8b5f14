// The fidelity comparison in shards: a shard's situations as the results of its shard
// file (report/shard_file.h), and the whole result again from all shards. An item is a situation
// of the set; its result is everything RunFidelity computed for it (candidates with their three
// evaluations, metrics, decisions, the drawn outcomes, the recorded trials of a situation that may
// get a 3D viewer, validation/fidelity_views.h), numbers written exactly, so the merged report has
// the bytes of an unsharded run.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "report/shard_file.h"
#include "validation/fidelity.h"

namespace foresight {

// The results of a sharded RunFidelity's situations, in set order.
nlohmann::json FidelityShardResults(const FidelityResult& result);

// The whole run's result from its shards (ReadShardParts' order), finished: the same as an
// unsharded RunFidelity of `set` with `settings`. InputError when a result is malformed.
FidelityResult MergeFidelityShards(const FidelitySet& set, const FidelitySettings& settings,
                                   const std::vector<ShardPart>& parts);

}  // namespace foresight
