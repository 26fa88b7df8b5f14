// `foresight decide`: the coarse decision on one situation file.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace foresight {

struct DecideOptions {
  std::string situation_file;
  std::string kicks_file;  // replaces the situation's kick model when given
  std::string strategy = "optimal_all";
  std::string samples;  // empty: the evaluation file's N
  std::string seed = "1";
  bool json = false;
  std::string svg_file;
};

void AddDecideCommand(CLI::App& app, DecideOptions& options);

// Runs the command; bad input throws InputError. Returns the exit code.
int RunDecide(const DecideOptions& options, const std::string& models_dir);

}  // namespace foresight
