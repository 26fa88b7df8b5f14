// The two conditions a gameplay must meet (Ros et al. 2009, sec. 2.2), as cbr/case_file.h
// defines them precisely: one robot gets the ball first, and the ball is controlled by one robot
// at a time, handed on only by a pass its receiver receives.
#pragma once

#include "cbr/case.h"

namespace foresight {

// Throws InputError "teammates[I].actions[J]: problem" for the first action that breaks a rule,
// with I, J the positions in c.teammates and their action lists.
void ValidateGameplay(const Case& c);

}  // namespace foresight
