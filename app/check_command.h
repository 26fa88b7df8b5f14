// `foresight check`: physics expectations from a spec file; exit code 1 when one fails, and a
// JUnit XML file for CI systems.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace foresight {

struct CheckOptions {
  std::string spec_file;  // default: MODELS/check_specs/default.json
  std::string junit_file;
  std::string threads = "0";
  std::string base;  // --base: empty, the physics files'
};

void AddCheckCommand(CLI::App& app, CheckOptions& options);
// 0: every check passed; 1: at least one failed. Bad input throws InputError.
int RunCheckCommand(const CheckOptions& options, const std::string& models_dir);

}  // namespace foresight
