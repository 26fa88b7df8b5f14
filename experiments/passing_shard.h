// The passing experiment and its ablations in shards: a shard's trials as the
// results of its shard file (report/shard_file.h), and every team's result again from all
// shards. The items of a run are the trials of its teams (`--team both`: cbr, reactive; the
// ablations: reactive and every variant), team by team, scenario by scenario: trial i of the
// k-th scenario of the t-th team is item (t * scenarios + k) * trials + i. Interleaved over the
// shards (common/shard.h), every shard gets trials of every team and scenario, so the slow CBR
// trials spread evenly. A trial's random numbers come from its scenario and index only
// (PassingTrialKey), so the merge gives the unsharded results bit for bit, whatever N.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/passing.h"
#include "report/shard_file.h"

namespace foresight {

// The run's item count: the trials of `teams` teams.
int PassingItems(const PassingSetup& setup, int teams);

// The trials of `team` (the t-th of a sharded run) are items t * per team on: RunPassing with
// this shard plays the team's trials that `shard` owns.
Shard TeamShard(const PassingSetup& setup, int team, const Shard& shard);

// The results of `shard`'s trials in `results` (one per entry of `teams`, played with
// TeamShard), in item order: {"team": NAME, "scenario": N, "trial": I, "result": TRIAL}.
nlohmann::json PassingShardResults(const PassingSetup& setup, const std::vector<std::string>& teams,
                                   const std::vector<PassingResult>& results, const Shard& shard);

// Every team's result from the shards (ReadShardParts' order): the same as the unsharded
// RunPassing's. InputError naming the file and place when a result is malformed or is not the
// trial it should be.
std::vector<PassingResult> MergePassingShards(const PassingSetup& setup,
                                              const std::vector<std::string>& teams,
                                              const std::vector<ShardPart>& parts);

}  // namespace foresight
