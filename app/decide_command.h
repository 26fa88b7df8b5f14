// `foresight decide`: the coarse decision on one situation file.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
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

// What `decide --json` prints, without printing it (the Python module's decide).
nlohmann::ordered_json DecideJson(const DecideOptions& options, const std::filesystem::path& models);

}  // namespace foresight
