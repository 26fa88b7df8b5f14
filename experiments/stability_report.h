// What `foresight experiment stability` writes: JSON (the contract), a CSV per sample count, a
// CSV per grid position (the field map's data), the log-log plot like the paper's Fig. 4, the
// field map, and a short text for the terminal.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "experiments/stability.h"
#include "report/provenance.h"

namespace foresight {

struct StabilityRun {
  // Inputs: "file" (the params file), "situation" (the scene's name), "kicks".
  RunProvenance provenance;
  const StabilityParams* params = nullptr;
  StabilityResult result;
};

// The largest share of poses with a most likely decision of <= 20 % over the sample counts
// >= `min_samples` (the paper: about 10 % from 20 samples on); NaN if no count qualifies.
double WorstUncertainShareFrom(const StabilityResult& result, int min_samples);

std::string StabilityText(const StabilityRun& run);
nlohmann::ordered_json StabilityJson(const StabilityRun& run);
std::string StabilityCountsCsv(const StabilityRun& run);
std::string StabilityPositionsCsv(const StabilityRun& run);
std::string StabilityPlotSvg(const StabilityRun& run);
std::string StabilityMapSvg(const StabilityRun& run);

}  // namespace foresight
