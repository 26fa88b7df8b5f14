// The problem a team wants a case for (Ros et al. 2009, sec. 2.1): the ball, the defending
// goal, the teammates that may take part (id, pose) and the opponents the team sees, all global
// in the Four-Legged field's frame F (cbr/case.h). Loaded from a problem file (cbr/problem.cc).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "cbr/case.h"
#include "common/geometry.h"
#include "models/model_paths.h"

namespace foresight {

struct ProblemTeammate {
  int id = 0;  // 1..4
  Pose2 pose;
};

struct Problem {
  Vec2 p_F_ball{0.0, 0.0};
  DefendingGoal defending = DefendingGoal::kCyan;
  std::vector<ProblemTeammate> teammates;  // 1-4, distinct ids
  std::vector<Vec2> opponents;             // 0-4, positions in F
};

// Reads a problem file, strictly (unknown keys are errors):
//   {"notes": "...",                       optional
//    "field": "four_legged",               optional, the field positions are checked against
//    "defending": "cyan",
//    "ball": {"x_m": 1.0, "y_m": 0.2},
//    "teammates": [{"id": 1, "x_m": 0.8, "y_m": 0.2, "theta_deg": 0}],      1-4, ids 1..4 distinct
//    "opponents": [{"x_m": 2.0, "y_m": 0.0}]}                                optional, 0-4
// Positions must lie on the field. Errors read "FILE: FIELD: problem". A bare field name is found
// in MODELS_DIR/fields (models/model_paths.h).
Problem LoadProblem(const std::filesystem::path& file,
                    const std::filesystem::path& models_dir = DefaultModelsDir());
// The same from a problem file's text that came from elsewhere (the Python module's dicts):
// `origin` names it in messages; a field path ending in ".json" resolves against `dir`.
Problem ParseProblem(std::string_view text, const std::string& origin,
                     const std::filesystem::path& dir,
                     const std::filesystem::path& models_dir = DefaultModelsDir());

}  // namespace foresight
