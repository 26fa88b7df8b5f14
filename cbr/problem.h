// The problem a team wants a case for (Ros et al. 2009, sec. 2.1): the ball, the defending
// goal, the teammates that may take part (id, pose) and the opponents the team sees, all global
// in the Four-Legged field's frame F (cbr/case.h). Loaded from a problem file (cbr/problem.cc).
#pragma once

#include <filesystem>
#include <vector>

#include "cbr/case.h"
#include "common/geometry.h"

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

}  // namespace foresight
