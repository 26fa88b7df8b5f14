// The CBR team's ablations: the reactive team and every variant of
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

// The teams of an ablation run in play order, the reactive team first: "reactive" and the
// variants' names. Their trials are the run's items team by team (experiments/passing_shard.h).
std::vector<std::string> AblationTeams(const std::vector<PassingVariant>& variants);

// Plays the reactive team and every variant, one result per AblationTeams entry; progress(done,
// total) counts trials over all. The trials keep their outcome and counters, not their event
// logs and traces, which no ablation output reads. With a shard other than the whole run (issue
// 17) only its trials are played (the teams' trials numbered one team after the other).
std::vector<PassingResult> PlayAblations(const PassingSetup& base,
                                         const std::vector<PassingVariant>& variants,
                                         const KickExecutor& executor, std::uint64_t seed,
                                         int threads,
                                         const std::function<void(int, int)>& progress = {},
                                         const Shard& shard = {});

// The summaries and paired comparisons of every team's results (PlayAblations' order).
AblationRun SummariseAblations(const PassingSetup& base, std::vector<PassingVariant> variants,
                               const std::vector<PassingResult>& results);

nlohmann::ordered_json AblationsJson(const AblationRun& run);
std::string AblationsCsv(const AblationRun& run);
std::string AblationsText(const AblationRun& run);
std::string AblationsSvg(const AblationRun& run);

}  // namespace foresight
