// 3D viewer pages (report/viewer_page.h) of a fidelity run's worst situations (WorstFirst): for
// each, the coarse model's choice and physics's best candidate, each with its first physics
// trials and their recorded scenes.
//
// The worst situations are known only when every situation has run (in shards: when they are
// merged), but a trial can be recorded only while its evaluator exists. So each situation, once
// scored, is recorded if it is among the worst shown of the situations run so far (MayBeShown),
// by playing its shown trials again through the very function that scored them
// (PhysicsActionEvaluator::Replay, which refuses a replay whose outcome differs from the scored
// one by a bit), and a situation pushed out of that group drops its recordings (KeepShownViews).
// The worst shown of a whole run are among the worst shown of every shard's own situations
// (WorseSituation is a strict weak order), so a shard file carries the recordings its situations
// may need, and merging the shards and writing the pages runs no physics. The price: at most
// 2 x kFidelityViewTrials extra trials per situation (each records only itself), usually fewer.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "models/robot_spec.h"
#include "validation/fidelity.h"
#include "validation/physics_evaluator.h"

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

// The situations that get a viewer (indices into `situations`), worst first: the first
// kFidelityViewSituations of WorstFirst in which a candidate shown kicks.
std::vector<int> FidelityViewSituations(const std::vector<SituationFidelity>& situations);

// Whether `s`, run after `before` (in set order), is among the situations that get a viewer of
// before and s together.
bool MayBeShown(const std::vector<SituationFidelity>& before, const SituationFidelity& s);

// The shown candidates' first trials of `s`, played again by `physics` (which scored them) with
// their scenes recorded.
std::vector<ViewerTrial> RecordFidelityViews(const SituationFidelity& s,
                                             PhysicsActionEvaluator& physics);

// Drops the recordings of every situation that no longer gets a viewer.
void KeepShownViews(std::vector<SituationFidelity>& situations);

// (file name, page) of every viewer, in FidelityViewSituations' order, from the recorded views;
// `robots` draws each situation's robot (by its name). InputError if a shown situation has no
// recordings (a shard written without them).
std::vector<std::pair<std::string, std::string>> FidelityViewPages(
    const FidelityResult& result, const FidelitySettings& settings,
    const std::filesystem::path& models);

}  // namespace foresight
