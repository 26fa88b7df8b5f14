// Variants of the CBR team for ablations (the paper reports none). Each variant
// changes a few parameters of the paper's team; models/experiments/cbr_variants.json lists them:
//   {"notes": "...",
//    "variants": [
//      {"name": "paper", "notes": "..."},                                    no change
//      {"name": "max_cost", "notes": "...", "retrieval": {"cost": "max"}},
//      ...]}
// Keys a variant may change (strict; each optional):
//   retrieval:  cost ("sum", "max", "max_then_sum"), order (the three criteria), free_path and
//               opponent_similarity (true/false);
//   team:       positioning ("dependent", "independent"), retrievers (1-4), pass_timing (true:
//               the timing-aware pass check of cbr/pass_timing.h), ball_race and kick_race
//               (true/false: cbr/ball_race.h, cbr/kick_race.h);
//   simulation: message_loss_rate, ball_noise_sigma_m, robot_noise_sigma_m;
//   cases:      mirror_y (false: the case base without its y-mirrored copies, CaseBase::
//               WithoutMirrorY).
// Names are unique; the first variant is the reference the others are compared with.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "experiments/passing.h"

namespace foresight {

struct PassingVariant {
  std::string name;
  std::string notes;
  std::optional<CostFunction> cost;
  std::optional<std::array<RankCriterion, 3>> order;
  std::optional<bool> free_path;
  std::optional<bool> opponent_similarity;
  std::optional<Positioning> positioning;
  std::optional<int> retrievers;
  std::optional<bool> pass_timing;
  std::optional<bool> ball_race;
  std::optional<bool> kick_race;
  std::optional<double> message_loss_rate;
  std::optional<double> ball_noise_sigma_m;
  std::optional<double> robot_noise_sigma_m;
  std::optional<bool> mirror_y;

  // `base` with this variant's changes, checked like the files they replace.
  PassingSetup Apply(const PassingSetup& base) const;
};

// `reference`: a bare name in MODELS/experiments/ ("cbr_variants") or a path ending in ".json".
std::vector<PassingVariant> LoadPassingVariants(const std::string& reference,
                                                const std::filesystem::path& models_dir);

}  // namespace foresight
