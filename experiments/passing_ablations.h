// The CBR team's ablations (issue 15): the reactive team and every variant of
// models/experiments/cbr_variants.json (experiments/passing_variants.h) play the same scenarios
// from the same trial keys, so each variant is compared with the paper's team (the first
// variant) and with the reactive team trial by trial (experiments/passing_comparison.h).
// Outputs: JSON (the contract), a CSV with one row per variant and scenario, a text table and a
// figure of the "to goal" shares with their intervals.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/passing_comparison.h"
#include "experiments/passing_variants.h"
#include "report/provenance.h"

namespace foresight {

struct AblationRun {
  RunProvenance provenance;
  const PassingSetup* base = nullptr;
  std::vector<PassingVariant> variants;
  std::vector<ScenarioSummary> reactive;
  std::vector<std::vector<ScenarioSummary>> summaries;  // per variant
  std::vector<PassingComparison> vs_reference;          // per variant (the first: with itself)
  std::vector<PassingComparison> vs_reactive;           // per variant
};

// Plays the reactive team and every variant; progress(done, total) counts trials over all.
AblationRun RunAblations(const PassingSetup& base, std::vector<PassingVariant> variants,
                         const KickExecutor& executor, std::uint64_t seed, int threads,
                         const std::function<void(int, int)>& progress = {});

nlohmann::ordered_json AblationsJson(const AblationRun& run);
std::string AblationsCsv(const AblationRun& run);
std::string AblationsText(const AblationRun& run);
std::string AblationsSvg(const AblationRun& run);

}  // namespace foresight
