// What `foresight decide` shows of a decision: the decided run that its text table
// (app/decision_text.h), JSON (the contract, app/decision_json.h) and SVG drawing of the
// hypotheses in the manner of Mellmann & Schlotter's Fig. 2 (app/decision_svg.h) are made from.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "planner/coarse_planner.h"

namespace foresight {

struct DecisionRun {
  std::filesystem::path situation_file;
  const CoarsePlanner* planner = nullptr;
  Decision decision;
  int samples = 0;
  std::uint64_t seed = 0;
  std::filesystem::path models_dir;  // data files below it are reported relative to it
};

// The name of kick `index` of the run's model, or "none" for -1.
std::string KickName(const DecisionRun& run, int kick_index);

}  // namespace foresight
