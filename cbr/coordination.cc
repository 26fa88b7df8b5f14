#include "cbr/coordination.h"

#include <cmath>

namespace foresight {

int Selector(std::span<const TeammateBelief> team) {
  for (std::size_t i = 0; i < team.size(); ++i) {
    if (team[i].present) return static_cast<int>(i);
  }
  return -1;
}

int ChooseCoordinator(std::span<const TeammateBelief> team, int retrievers) {
  int best = -1;
  for (std::size_t i = 0; i < team.size() && static_cast<int>(i) < retrievers; ++i) {
    if (!team[i].present) continue;
    if (!std::isfinite(team[i].ball_distance_m)) return -1;
    if (best < 0 || team[i].ball_distance_m < team[static_cast<std::size_t>(best)].ball_distance_m) {
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace foresight
