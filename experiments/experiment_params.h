// Parameters of the paper's two experiments (Mellmann & Schlotter, sec. V), read from
// models/experiments/*.json. The shipped files hold the paper's defaults; code repeats none.
//
// Both experiments take their scene from a situation file ("situation"): field, kick model,
// evaluation, the belief's sigmas, where the ball lies at the robot's feet (ball.x_m, ball.y_m
// relative to the robot) and any obstacles. Its robot pose is replaced by every pose the
// experiment visits.
//
// stability (sec. V-A):
//   {"situation": "experiment_nao", "strategy": "naoth", "grid_step_m": 0.3,
//    "heading_step_deg": 5, "repeats": 100, "sample_counts": [1, 2, ...], "map_samples": 30,
//    "rotation_bin_deg": 10}
// strategies (sec. V-B):
//   {"situation": "experiment_nao", "strategies": ["fast", ...], "starts": 10000,
//    "max_steps": 100, "walk_speed_mps": 0.2, "turn_speed_deg_per_s": 60,
//    "turn_around_ball_speed_deg_per_s": 30, "example_start": 0}
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "models/situation.h"
#include "planner/decision.h"

namespace foresight {

struct StabilityParams {
  std::filesystem::path file;  // where these were read from (for reports)
  Situation situation;
  Strategy strategy = Strategy::kNaoth;
  double grid_step_m = 0.0;        // cell size of the position grid over the field
  double heading_step_rad = 0.0;   // headings 0, step, 2 step, ... below 2 pi
  int repeats = 0;                 // decisions per pose and sample count (R)
  std::vector<int> sample_counts;  // N values, ascending, distinct
  int map_samples = 0;             // the N whose stability the field map shows (one of the list)
  double rotation_bin_rad = 0.0;   // turns in one bin of this width count as the same decision

  void Validate() const;  // InputError naming the field and value
};

struct StrategiesParams {
  std::filesystem::path file;
  Situation situation;
  std::vector<Strategy> strategies;
  int starts = 0;     // random start positions
  int max_steps = 0;  // decisions per run at most (the step limit)
  double walk_speed_mps = 0.0;
  double turn_speed_radps = 0.0;              // turning on the spot (towards the ball)
  double turn_around_ball_speed_radps = 0.0;  // turning around the ball before a kick
  int example_start = 0;                      // the start whose ball paths are drawn (Fig. 3)

  void Validate() const;
};

// `params` is a file, or a bare name found as MODELS/experiments/<name>.json. `overrides` apply to
// the scene's situation (a kick model, the coarse rebounds). Throws InputError on bad input.
StabilityParams LoadStabilityParams(const std::string& params,
                                    const std::filesystem::path& models_dir,
                                    const SituationOverrides& overrides = {});
StrategiesParams LoadStrategiesParams(const std::string& params,
                                      const std::filesystem::path& models_dir,
                                      const SituationOverrides& overrides = {});

// Parses "1-25,30-110/10" style lists: items separated by commas, each a number or a range
// lo-hi with an optional /step (default 1). InputError naming `field` on bad text.
std::vector<int> ParseSampleCounts(const std::string& field, const std::string& text);

}  // namespace foresight
