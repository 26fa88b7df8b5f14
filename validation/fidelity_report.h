// What a fidelity run writes: JSON (the contract), CSV (one row per candidate), an HTML page
// with inline SVG, and a short text for the terminal.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "validation/fidelity.h"

namespace foresight {

struct FidelityRun {
  std::string version;
  std::string set_name, set_file, physics_file;
  FidelitySettings settings;
  std::vector<double> rotations_rad;
  FidelityResult result;
  double run_time_s = 0.0;
};

std::string FidelityText(const FidelityRun& run);
nlohmann::ordered_json FidelityJson(const FidelityRun& run);
std::string FidelityCandidatesCsv(const FidelityRun& run);
std::string FidelitySituationsCsv(const FidelityRun& run);

}  // namespace foresight
