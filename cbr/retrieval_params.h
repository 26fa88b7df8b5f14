// The parameters of case retrieval (Ros, Arcos, López de Mántaras, Veloso 2009, sec. 3), with the
// paper's values as defaults (models/cbr/retrieval.json repeats them with their sections):
//   thr_b   = exp(-1) ~ 0.367: ball similarity threshold (sec. 3.1, the scope ellipse's edge);
//   thr_c   = 1.5 m:           the farthest a matched robot may have to walk (sec. 3.2, 3.4);
//   thr_t   = exp(-1):         a point is on a fuzzy ball trajectory if mu > thr_t (sec. 3.3.1);
//   thr_opp = exp(-1):         an opponent occupies a case scope if Omega > thr_opp (sec. 3.3.2);
//   similarity bands H = [0.8, 1], h = [0.6, 0.8), l = [0.4, 0.6), L = (0, 0.4) (sec. 3.4);
//   cost = sum of the distances to the adapted positions (sec. 3.2; max and max-then-sum are the
//          alternatives the paper discusses with Fig. 6);
//   ranking: conditions, then teammates, then band-then-cost (sec. 3.4, "the most suitable").
// Fuzzy trajectory widths per kick (sec. 3.3.1, Fig. 7: r_min 0.1 m, r_max 0.3 m for l 0.5 m) are
// data, or derived from the kick model's direction noise (cbr/free_path.h).
#pragma once

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "models/field_spec.h"

namespace foresight {

struct KickModel;

// How the matched robots' distances aggregate into the adaptation cost (sec. 3.2).
enum class CostFunction {
  kSum,         // sum of distances (the paper's choice)
  kMax,         // the largest distance (Fig. 6: paths may cross)
  kMaxThenSum,  // the largest distance, ties broken by the sum
};

// The criteria of the ranking of candidates (sec. 3.4), applied in the order of
// RetrievalParams::order.
enum class RankCriterion {
  kConditions,    // fulfilled opponent scopes, more is better
  kTeammates,     // teammates in the gameplay, more is better
  kBandThenCost,  // similarity band (H before h before l before L), then lower cost
};

// Where a fuzzy trajectory's widths come from.
enum class TrajectoryWidths {
  kData,       // r_min_m, r_max_m of the kick's entry
  kKickModel,  // radii plus x * tan(width_sigmas * sigma_direction) (cbr/free_path.h)
};

// One kick's fuzzy trajectory (sec. 3.3.1). `kick` names a kick of the kick model; the entry
// RetrievalParams::default_kick serves every kick that has no entry of its own.
struct KickTrajectory {
  std::string kick;
  double r_min_m = 0.1;  // half-width of the exp(-1) edge at the start (Fig. 7)
  double r_max_m = 0.3;  // ... at the end
  double reach_m = 0.0;  // > 0: the trajectory ends after at most this length; 0: at its target
  double sigma_direction_rad = 0.0;  // > 0 with kKickModel: widths from the kick model
  double roll_m = 0.0;  // > 0: the kick's mean roll, where a kick into the field stops on average
};

struct RetrievalParams {
  double thr_ball = std::exp(-1.0);
  double thr_cost_m = 1.5;
  double thr_trajectory = std::exp(-1.0);
  double thr_opponent = std::exp(-1.0);
  // Lower edges of the bands H, h, l (inclusive); L is (0, band_lower[2]).
  std::array<double, 3> band_lower{0.8, 0.6, 0.4};
  CostFunction cost = CostFunction::kSum;
  std::array<RankCriterion, 3> order{RankCriterion::kConditions, RankCriterion::kTeammates,
                                     RankCriterion::kBandThenCost};
  // x of the centre of the goal a team defending cyan attacks (the other: -goal_x_m). This and
  // the two radii below are set from the field by LoadRetrievalParams; the defaults are the
  // Four-Legged field's (models/fields/four_legged.json) for parameters built in code.
  double goal_x_m = 2.7;
  double half_width_m = 1.8;        // the side lines' |y| (four_legged.json field_width_m / 2)
  TrajectoryWidths widths = TrajectoryWidths::kData;
  double width_sigmas = 1.0;        // k of the kick-model widths
  double opponent_radius_m = 0.12;  // four_legged.json default_obstacle_radius_m
  double ball_radius_m = 0.042;     // four_legged.json ball.radius_m
  KickTrajectory default_kick{"default"};
  std::vector<KickTrajectory> kicks;
  // z of the roll at which a kick's trajectory ends (planner/kick_reach.h), set per kick by
  // UseKickModelReach; absent: trajectories run to their targets (the paper's ball path).
  std::optional<double> reach_sigmas;
  // Ablation switches (the paper always uses both): without the free-path filter no
  // case is rejected for an opponent on its ball path; without opponent similarity every
  // candidate fulfils 0 conditions, so that criterion never decides.
  bool free_path = true;
  bool opponent_similarity = true;

  // The entry of `kick`, or default_kick.
  const KickTrajectory& TrajectoryFor(std::string_view kick) const;
  void Validate() const;
};

// Copies each kick's sigma_direction_rad from `model` into params->kicks (adding entries with
// the default widths for kicks that have none) and selects TrajectoryWidths::kKickModel.
void UseKickModelWidths(const KickModel& model, RetrievalParams* params);

// With params->reach_sigmas: sets every kick's reach_m to the roll of `model`'s kick at
// reach_sigmas sd of its launch speed and roll_m to its mean roll (adding entries with the
// default widths for kicks that have none), so a case's ball path ends where its kicks end.
// Without: nothing changes.
void UseKickModelReach(const KickModel& model, RetrievalParams* params);

// Reads `file`; the goal line, the opponents' and the ball's radii come from `field` (the field
// the case base is written for), not from the file, so no number is written twice.
RetrievalParams LoadRetrievalParams(const std::filesystem::path& file, const FieldSpec& field);

// Names as the JSON file spells them ("sum", "max_then_sum"; "conditions", "teammates",
// "band_then_cost"; "data", "kick_model").
std::string_view CostFunctionName(CostFunction cost);
std::optional<CostFunction> ParseCostFunction(std::string_view name);
std::optional<RankCriterion> ParseRankCriterion(std::string_view name);
std::string CostFunctionNames();   // "sum, max, max_then_sum" for messages
std::string RankCriterionNames();
std::string_view RankCriterionName(RankCriterion criterion);
std::string_view TrajectoryWidthsName(TrajectoryWidths widths);

}  // namespace foresight
