// `foresight merge --out DIR SHARD_DIR...`: the report of a run made in shards (--shard I/N),
// byte for byte what the unsharded run writes (its run time aside: the sum of the shards').
// Shards of different runs (command, version, settings, shard count), a shard given twice or a
// missing one end in one line and exit 2 (report/shard_file.h), and so does an --out that is or
// holds one of the shard folders (the report would replace it).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace foresight {

struct MergeOptions {
  std::vector<std::string> shard_dirs;
  std::string out_dir;
};

void AddMergeCommand(CLI::App& app, MergeOptions& options);
int RunMergeCommand(const MergeOptions& options, const std::string& models_dir);

}  // namespace foresight
