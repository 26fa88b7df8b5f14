// 3D viewer pages (report/viewer_page.h) of a fidelity run's worst situations (WorstFirst): for
// each, the coarse model's choice and physics's best candidate, each with its first physics
// trials played again with the scene recorded. They are the very trials fidelity scored: trial i
// draws sample i of the same seed and the same physics stream (validation/physics_evaluator.h),
// and a trial is deterministic.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "validation/fidelity.h"

namespace foresight {

// How many of the worst situations get a viewer, and how many trials of each candidate it shows.
inline constexpr int kFidelityViewSituations = 3;
inline constexpr int kFidelityViewTrials = 3;
// Frames per simulated second recorded for the viewers (as `simulate --view-rate`'s default).
inline constexpr double kFidelityViewRateHz = 100.0;

// The file name of viewer k (0: the worst situation's).
std::string FidelityViewFile(int k);

// "forward 30 deg": a candidate as the fidelity report names it.
std::string FidelityActionText(const Situation& situation, int kick, double rotation_rad);

// The situations that get a viewer (indices into result.situations), worst first: the first
// kFidelityViewSituations of WorstFirst in which a candidate shown kicks.
std::vector<int> FidelityViewSituations(const FidelityResult& result);

// (file name, page) of every viewer, in FidelityViewSituations' order.
std::vector<std::pair<std::string, std::string>> FidelityViewPages(
    const FidelityResult& result, const FidelitySettings& settings,
    const std::filesystem::path& models);

}  // namespace foresight
