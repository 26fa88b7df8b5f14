// `foresight experiment passing`: 2-vs-2 attacks of the reactive or the CBR team (or both,
// paired) against the DG or 2D opponents (Ros et al. 2009, sec. 5.2), in one run or in shards
// (--shard I/N: a slice of the trials of every team, experiments/passing_shard.h) merged by
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

inline constexpr char kPassingCommand[] = "experiment passing";

void AddPassingCommand(CLI::App& experiment, PassingOptions& options);
int RunPassingCommand(const PassingOptions& options, const std::filesystem::path& models);
// The report of the shards of one passing run in `out_dir`.
int MergePassingCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                        const std::string& out_dir, const std::filesystem::path& models);

}  // namespace foresight
