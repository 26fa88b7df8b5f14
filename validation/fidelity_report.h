// What a fidelity run writes: JSON (the contract), CSV (one row per candidate), an HTML page
// with inline SVG, and a short text for the terminal.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "report/provenance.h"
#include "validation/fidelity.h"

namespace foresight {

struct FidelityRun {
  // Inputs: "situations_set" (the set's name), "set_file", "physics_file"; the seed is the
  // settings' seed.
  RunProvenance provenance;
  FidelitySettings settings;
  std::vector<double> rotations_rad;
  FidelityResult result;
};

std::string FidelityText(const FidelityRun& run);
nlohmann::ordered_json FidelityJson(const FidelityRun& run);
std::string FidelityCandidatesCsv(const FidelityRun& run);
std::string FidelitySituationsCsv(const FidelityRun& run);

}  // namespace foresight
