// Whether the opponents a case describes can stand where it puts them: in the paper's games
// every opponent keeps to its home region (Ros et al. 2009, sec. 5.1.2), so a case whose
// opponents no configuration can field at once describes a situation that never arises, and
// its conditions (sec. 3.3.2) are never all met: in a real game it scores fewer than it lists
// and is ranked beside cases written for other configurations.
#pragma once

#include <span>

#include "cbr/case.h"
#include "models/field_box.h"

namespace foresight {

// True when each of `c`'s opponents stands in the home region of a different one of
// `regions_F` (one configuration's opponents, for a team defending cyan; a case defending
// yellow is compared mirrored in x). A case without opponents is fielded by every configuration.
bool FieldsCaseOpponents(const Case& c, std::span<const FieldBox> regions_F);

}  // namespace foresight
