// What `foresight experiment strategies` writes: JSON (the contract: parameters and the summary
// per strategy), a CSV with one row per run, the histogram of turns around the ball (log scale,
// turns of 0 left out, like the paper's Fig. 5 top), the histogram of kicks until goal or out
// (Fig. 5 bottom), the ball paths of every strategy from one start (Fig. 3), and a terminal text.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/strategy_stats.h"

namespace foresight {

struct StrategiesRun {
  std::string version;
  std::string params_file, situation_name, kicks_file;  // files as displayed
  std::string executor;                                 // "coarse" or "physics"
  std::string physics_file;                             // with physics, as displayed
  const StrategiesParams* params = nullptr;
  std::uint64_t seed = 0;
  StrategiesResult result;
  std::vector<StrategySummary> summaries;
  double run_time_s = 0.0;
};

std::string StrategiesText(const StrategiesRun& run);
nlohmann::ordered_json StrategiesJson(const StrategiesRun& run);
std::string StrategiesRunsCsv(const StrategiesRun& run);
std::string StrategiesTurnsSvg(const StrategiesRun& run);
std::string StrategiesKicksSvg(const StrategiesRun& run);
std::string StrategiesPathsSvg(const StrategiesRun& run);

}  // namespace foresight
