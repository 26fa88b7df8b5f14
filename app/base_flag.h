// `--base fixed|floating` on the commands that run physics trials: the kicking robot's base
// (models/physics_params.h, RobotBase), replacing the physics file's `robot.base`. Empty: the
// file's.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "models/physics_params.h"

namespace foresight {

// InputError "--base: must be one of fixed, floating, got 'TEXT'".
std::optional<RobotBase> ParseBaseFlag(const std::string& text);

// The base a run's trials use, as its records name it: `flag` (--base) when given, else the
// `robot.base` of each physics file the run reads, distinct ones joined in the order read
// ("floating"; "fixed, floating" when the files differ).
std::string BaseUsed(const std::optional<RobotBase>& flag,
                     const std::vector<std::filesystem::path>& physics_files);
void AddBaseOption(CLI::App& command, std::string& text);

}  // namespace foresight
