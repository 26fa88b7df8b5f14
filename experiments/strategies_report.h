// What `foresight experiment strategies` writes: JSON (the contract: parameters and the summary
// per strategy), a CSV with one row per run, the histogram of turns around the ball (log scale,
// turns of 0 left out, like the paper's Fig. 5 top), the histogram of kicks until goal or out
// (Fig. 5 bottom), the ball paths of every strategy from one start (Fig. 3), and a terminal text.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/strategy_stats.h"
#include "report/provenance.h"

namespace foresight {

struct StrategiesRun {
  // Inputs: "file" (the params file), "situation" (the scene's name), "kicks", "executor"
  // ("coarse" or "physics": what executed the kicks) and, with physics, "physics" (its file).
  RunProvenance provenance;
  const StrategiesParams* params = nullptr;
  StrategiesResult result;
  std::vector<StrategySummary> summaries;
};

std::string StrategiesText(const StrategiesRun& run);
nlohmann::ordered_json StrategiesJson(const StrategiesRun& run);
std::string StrategiesRunsCsv(const StrategiesRun& run);
std::string StrategiesTurnsSvg(const StrategiesRun& run);
std::string StrategiesKicksSvg(const StrategiesRun& run);
std::string StrategiesPathsSvg(const StrategiesRun& run);

}  // namespace foresight
