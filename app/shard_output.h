// `--shard I/N` on the long commands and what a shard writes: instead of its report,
// a sharded run writes DIR/shard.json (report/shard_file.h) into its --out folder, which is a
// report folder like any other (written whole, only over a folder foresight made).
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <optional>
#include <string>

#include "common/shard.h"
#include "report/output_set.h"
#include "report/shard_file.h"

namespace foresight {

void AddShardOption(CLI::App& command, std::string& shard);

// The parsed --shard, or nothing when the flag was not given.
std::optional<Shard> ParseShardFlag(const std::string& text);

// Commits `out_dir`/shard.json as the folder --out that `outputs` declared before the work
// (ReportFolderOutput) and prints what it holds and how to merge.
void WriteShardFolder(OutputSet& outputs, const std::string& out_dir, ShardHeader header,
                      const nlohmann::json& results, std::chrono::steady_clock::time_point start,
                      const std::string& item_name);

// The sum of the shards' run times: the merged report's run time (the computing time; the wall
// time of a parallel run is shorter).
double ShardsRunTime(const std::vector<ShardPart>& parts);

// InputError unless the shards' run has `items` items (UNIT: "poses", "trials", ...) with the
// data files the merge finds: the data changed between the shards and the merge otherwise.
void RequireShardItems(const ShardPart& first, int items, const std::string& unit);

// The settings of a shard as the flag values they were given as.
std::string SettingString(const ShardPart& part, const std::string& flag);
bool SettingFlag(const ShardPart& part, const std::string& flag);

}  // namespace foresight
