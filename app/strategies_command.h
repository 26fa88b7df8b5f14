// `foresight experiment strategies`: the four strategies from random starts until goal or out
// (Mellmann & Schlotter, Figs. 3 and 5), in one run or in shards (--shard I/N) merged by
// `foresight merge` into the same report.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "report/output_set.h"
#include "report/shard_file.h"

namespace foresight {

inline constexpr char kStrategiesCommand[] = "experiment strategies";

struct StrategiesOptions {
  std::string params = "strategies";
  std::string kicks_file;
  std::string starts;  // empty: the params file's
  bool physics = false;
  std::string physics_file;
  std::string base;  // --base, with --physics; empty: the physics file's
  std::string coarse_rebounds;  // "on", "off" or empty (the evaluation file's)
  std::string seed = "1";
  std::string threads = "0";
  std::string out_dir;
  std::string shard;  // "I/N": only that shard (app/shard_output.h); empty: the whole run
};

void AddStrategiesCommand(CLI::App& experiment, StrategiesOptions& options);
int RunStrategiesCommand(const StrategiesOptions& options, const std::filesystem::path& models);
// The report of the shards of one strategies run in `out_dir`.
int MergeStrategiesCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                           const std::string& out_dir, const std::filesystem::path& models);

}  // namespace foresight
