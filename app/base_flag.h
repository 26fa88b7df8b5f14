// `--base fixed|floating` on the commands that run physics trials: the kicking robot's base
// (models/physics_params.h, RobotBase), replacing the physics file's `robot.base`. Empty: the
// file's.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "models/physics_params.h"

namespace foresight {

// InputError "--base: must be one of fixed, floating, got 'TEXT'".
std::optional<RobotBase> ParseBaseFlag(const std::string& text);
void AddBaseOption(CLI::App& command, std::string& text);

}  // namespace foresight
