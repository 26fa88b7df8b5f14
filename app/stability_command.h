// `foresight experiment stability`: how stable the decision is against the number of samples
// (Mellmann & Schlotter, Fig. 4), in one run or in shards (--shard I/N) merged by `foresight
// merge` into the same report.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "report/output_set.h"
#include "report/shard_file.h"

namespace foresight {

inline constexpr char kStabilityCommand[] = "experiment stability";

struct StabilityOptions {
  std::string params;  // empty: "stability" (or "stability_quick" with --quick)
  bool quick = false;
  std::string kicks_file;
  std::string strategy;  // empty: the params file's
  std::string repeats;   // empty: the params file's
  std::string samples;   // empty: the params file's; "1-25,30-110/10" style
  std::string seed = "1";
  std::string threads = "0";
  std::string out_dir;
  std::string shard;  // "I/N": only that shard (app/shard_output.h); empty: the whole run
};

void AddStabilityCommand(CLI::App& experiment, StabilityOptions& options);
int RunStabilityCommand(const StabilityOptions& options, const std::filesystem::path& models);
// The report of the shards of one stability run in `out_dir`.
int MergeStabilityCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                          const std::string& out_dir, const std::filesystem::path& models);

}  // namespace foresight
