#include "cbr/case_opponents.h"

#include <vector>

namespace foresight {

namespace {

// Assigns opponents[next..] to regions not yet taken; a case has few opponents, so the search
// over assignments is small.
bool Assign(std::span<const CaseOpponent> opponents, std::size_t next,
            std::span<const FieldBox> regions, std::vector<bool>& taken, bool mirror_x) {
  if (next == opponents.size()) return true;
  const Vec2& p = opponents[next].p_F;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    if (taken[r]) continue;
    const FieldBox region = mirror_x ? regions[r].MirroredX() : regions[r];
    if (!region.Contains(p)) continue;
    taken[r] = true;
    if (Assign(opponents, next + 1, regions, taken, mirror_x)) return true;
    taken[r] = false;
  }
  return false;
}

}  // namespace

bool FieldsCaseOpponents(const Case& c, std::span<const FieldBox> regions_F) {
  std::vector<bool> taken(regions_F.size(), false);
  return Assign(c.opponents, 0, regions_F, taken, c.defending == DefendingGoal::kYellow);
}

}  // namespace foresight
