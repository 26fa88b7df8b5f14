#include "app/merge_command.h"

#include <filesystem>
#include <system_error>

#include "app/calibrate_command.h"
#include "app/experiment_command.h"
#include "app/fidelity_command.h"
#include "common/error.h"
#include "models/model_paths.h"
#include "report/shard_file.h"

namespace foresight {

void AddMergeCommand(CLI::App& app, MergeOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "merge", "Make the report of a sharded run (--shard I/N) from all its shard folders");
  cmd->add_option("--out", options.out_dir, "Folder for the report")->required();
  cmd->add_option("shards", options.shard_dirs, "The --out folders of shards 0 .. N-1")
      ->required();
}

namespace {

// The report replaces --out whole: it must not be a shard folder it reads, nor hold one.
void RequireOutsideShards(const std::filesystem::path& out,
                          const std::vector<std::filesystem::path>& dirs) {
  std::error_code ec;
  const std::filesystem::path report = std::filesystem::weakly_canonical(out, ec);
  if (ec) return;  // checked again, with its reason, where the report is written
  for (const std::filesystem::path& dir : dirs) {
    const std::filesystem::path shard = std::filesystem::weakly_canonical(dir, ec);
    if (ec) continue;
    const std::filesystem::path relative = shard.lexically_relative(report);
    if (!relative.empty() && *relative.begin() != "..") {
      throw InputError("--out: " + out.string() + (relative == "." ? " is" : " holds") +
                       " the shard folder " + dir.string() +
                       ", which the report would replace; write the report elsewhere");
    }
  }
}

}  // namespace

int RunMergeCommand(const MergeOptions& options, const std::string& models_dir) {
  const std::filesystem::path models =
      models_dir.empty() ? DefaultModelsDir() : std::filesystem::path(models_dir);
  const std::vector<std::filesystem::path> dirs(options.shard_dirs.begin(),
                                                options.shard_dirs.end());
  RequireOutsideShards(options.out_dir, dirs);
  const std::vector<ShardPart> parts = ReadShardParts(dirs, FORESIGHT_VERSION);
  const std::string& command = parts.front().header.command;
  if (IsExperimentShardCommand(command))
    return MergeExperimentShards(parts, options.out_dir, models);
  if (command == kFidelityCommand) return MergeFidelityCommand(parts, options.out_dir, models);
  if (command == "calibrate") return MergeCalibrationCommand(parts, options.out_dir, models);
  throw InputError(parts.front().file.string() + ": command: '" + command +
                   "' is not a command that runs in shards");
}

}  // namespace foresight
