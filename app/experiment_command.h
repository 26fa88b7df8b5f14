// `foresight experiment stability|strategies|passing|ablations`: the first paper's two
// experiments (Mellmann & Schlotter, sec. V), the second paper's passing trials (Ros et al.
// 2009, sec. 5.2) and the CBR team's ablations, each writing JSON, CSV and SVG figures to a
// folder; one header per experiment (app/stability_command.h, ...), this one dispatches.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "app/ablations_command.h"
#include "app/passing_command.h"
#include "app/stability_command.h"
#include "app/strategies_command.h"
#include "report/output_set.h"
#include "report/shard_file.h"

namespace foresight {

struct ExperimentOptions {
  StabilityOptions stability;
  StrategiesOptions strategies;
  PassingOptions passing;
  PassingOptions ablations;  // the same inputs; the teams are the reactive one and the CBR variants
};

void AddExperimentCommand(CLI::App& app, ExperimentOptions& options);
// Runs the experiment subcommand that was given; 0 on success.
int RunExperimentCommand(const CLI::App& app, const ExperimentOptions& options,
                         const std::string& models_dir);

// `foresight merge` of the shards of an experiment (any of the four) into the report folder
// `out_dir`, the --out that `outputs` declared before the shards were read: the same files as
// the unsharded run.
bool IsExperimentShardCommand(const std::string& command);
int MergeExperimentShards(const std::vector<ShardPart>& parts, OutputSet& outputs,
                          const std::string& out_dir, const std::filesystem::path& models);

}  // namespace foresight
