// `foresight experiment ablations`: the reactive team and every variant of the CBR team
// (models/experiments/cbr_variants.json) from the same trial keys, in one run or in
// shards (--shard I/N: a slice of every team's trials, experiments/passing_shard.h) merged by
// `foresight merge` into the same report.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "app/passing_inputs.h"
#include "report/output_set.h"
#include "report/shard_file.h"

namespace foresight {

inline constexpr char kAblationsCommand[] = "experiment ablations";

void AddAblationsCommand(CLI::App& experiment, PassingOptions& options);
int RunAblationsCommand(const PassingOptions& options, const std::filesystem::path& models);
// The report of the shards of one ablations run in `out_dir`.
int MergeAblationsCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                          const std::string& out_dir, const std::filesystem::path& models);

}  // namespace foresight
