#include "app/merge_command.h"

#include <filesystem>

#include "app/calibrate_command.h"
#include "app/experiment_command.h"
#include "app/fidelity_command.h"
#include "common/error.h"
#include "models/model_paths.h"
#include "report/output_set.h"
#include "report/shard_file.h"

namespace foresight {

void AddMergeCommand(CLI::App& app, MergeOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "merge", "Make the report of a sharded run (--shard I/N) from all its shard folders");
  cmd->add_option("--out", options.out_dir, "Folder for the report")->required();
  cmd->add_option("shards", options.shard_dirs, "The --out folders of shards 0 .. N-1")
      ->required();
}

int RunMergeCommand(const MergeOptions& options, const std::string& models_dir) {
  const std::filesystem::path models =
      models_dir.empty() ? DefaultModelsDir() : std::filesystem::path(models_dir);
  const std::vector<std::filesystem::path> dirs(options.shard_dirs.begin(),
                                                options.shard_dirs.end());
  // The report replaces --out whole: it is checked before the shards are read, and it may not be
  // one of the shard folders nor hold one.
  OutputSet outputs;
  for (const std::filesystem::path& dir : dirs) outputs.AddInput("the shard folder", dir);
  outputs.AddFolder("--out", options.out_dir);
  const std::vector<ShardPart> parts = ReadShardParts(dirs, FORESIGHT_VERSION);
  const std::string& command = parts.front().header.command;
  const std::string& out = options.out_dir;
  if (IsExperimentShardCommand(command)) return MergeExperimentShards(parts, outputs, out, models);
  if (command == kFidelityCommand) return MergeFidelityCommand(parts, outputs, out, models);
  if (command == "calibrate") return MergeCalibrationCommand(parts, outputs, out, models);
  throw InputError(parts.front().file.string() + ": command: '" + command +
                   "' is not a command that runs in shards");
}

}  // namespace foresight
