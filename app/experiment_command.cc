#include "app/experiment_command.h"

#include "app/experiment_output.h"

namespace foresight {

void AddExperimentCommand(CLI::App& app, ExperimentOptions& options) {
  CLI::App* experiment = app.add_subcommand(
      "experiment", "The papers' experiments: stability, strategies, passing, ablations");
  experiment->require_subcommand(1);
  AddStabilityCommand(*experiment, options.stability);
  AddStrategiesCommand(*experiment, options.strategies);
  AddPassingCommand(*experiment, options.passing);
  AddAblationsCommand(*experiment, options.ablations);
}

int RunExperimentCommand(const CLI::App& app, const ExperimentOptions& options,
                         const std::string& models_dir) {
  const CLI::App* experiment = app.get_subcommand("experiment");
  const std::filesystem::path models = ModelsFolder(models_dir);
  if (experiment->got_subcommand("stability"))
    return RunStabilityCommand(options.stability, models);
  if (experiment->got_subcommand("passing")) return RunPassingCommand(options.passing, models);
  if (experiment->got_subcommand("ablations"))
    return RunAblationsCommand(options.ablations, models);
  return RunStrategiesCommand(options.strategies, models);
}

bool IsExperimentShardCommand(const std::string& command) {
  return command == kStabilityCommand || command == kStrategiesCommand ||
         command == kPassingCommand || command == kAblationsCommand;
}

int MergeExperimentShards(const std::vector<ShardPart>& parts, OutputSet& outputs,
                          const std::string& out_dir, const std::filesystem::path& models) {
  const std::string& command = parts.front().header.command;
  if (command == kStrategiesCommand) return MergeStrategiesCommand(parts, outputs, out_dir, models);
  if (command == kPassingCommand) return MergePassingCommand(parts, outputs, out_dir, models);
  if (command == kAblationsCommand) return MergeAblationsCommand(parts, outputs, out_dir, models);
  return MergeStabilityCommand(parts, outputs, out_dir, models);
}

}  // namespace foresight
