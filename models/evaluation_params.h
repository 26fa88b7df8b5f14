// The team strategy and decision thresholds (models/evaluation/*.json).
//
// Potential (Mellmann & Schlotter, sec. III-D; lower is better):
//   f(x, y) = -x / linear_x_scale_m + sum_k weight_k * G(x, y; centre_k; sigma_k),
//   G(x, y; cx, cy; sx, sy) = exp(-((x - cx)^2 / (2 sx^2) + (y - cy)^2 / (2 sy^2))).
// Utility (eq. 5): u = v_avg * p_infield + goal_value * p_goal; trimmed (eq. 6): u = 0 when
// p_out > max_out_share or any sample ends in the own goal.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace foresight {

// Samples per hypothesis, wherever they come from (file or --samples).
inline constexpr int kMaxSamples = 100000;

struct GaussianTerm {
  double weight = 0.0;
  double centre_x_m = 0.0;
  double centre_y_m = 0.0;
  double sigma_x_m = 1.0;
  double sigma_y_m = 1.0;
};

struct PotentialParams {
  double linear_x_scale_m = 1.0;
  std::vector<GaussianTerm> gaussians;
};

// NaoTH's published kick rule (used for comparison).
// The numbers live in models/evaluation/*.json only; zero-initialised structs fail Validate().
struct NaothRuleParams {
  double min_acceptable_share = 0.0;   // kicks at or below this share of infield+goal are dropped
  double goal_preference_share = 0.0;  // kicks with at least this goal share are preferred
};

// Search for the best rotation around the ball: a grid over the whole circle, then pattern
// refinement around the best grid points (see planner/rotation_search.h). The grid looks at
// the first ceil(coarse_sample_share * N) of the N samples only; the rest of the search, and
// every value the decision uses, at all N.
struct RotationSearchParams {
  double grid_step_rad = 0.0;
  int refine_levels = 0;
  int refine_candidates = 0;         // grid maxima compared on all N; the best is refined
  double coarse_sample_share = 1.0;  // 1: the grid on all N samples

  // The samples of the coarse stages for a decision of `samples` samples (1..samples).
  int CoarseSamples(int samples) const;
};

// The coarse roll's contacts with posts, nets and robots. Off, the paper's model: the
// ball stops where it first touches one (fully inelastic). On: it rebounds, reflected about the
// contact normal with its normal speed scaled by the pair's restitution (tangential speed kept),
// and rolls on; after max_contacts rebounds the next contact stops it.
struct CoarseRebounds {
  bool enabled = false;
  int max_contacts = 0;
  // The restitution of each pair, from the field's physics file (models/physics/<field>.json,
  // materials.restitution: ball_post, ball_net, ball_robot), read by LoadSituation when enabled,
  // so physics and the coarse model share one source. Zero until then.
  double post = 0.0;
  double net = 0.0;
  double robot = 0.0;
};

struct EvaluationParams {
  std::string name;
  PotentialParams potential;
  double goal_value = 0.0;     // v_max: value of a ball in the opponent goal
  double max_out_share = 0.0;  // T_out
  int samples = 0;             // N, samples per hypothesis
  NaothRuleParams naoth_rule;
  RotationSearchParams rotation_search;
  CoarseRebounds rebounds;  // enabled and max_contacts from the file

  void Validate() const;
};

EvaluationParams LoadEvaluationParams(const std::filesystem::path& file);

}  // namespace foresight
