// `foresight decide`'s drawing: the hypotheses on the field, like the paper's Fig. 2.
#pragma once

#include <string>

#include "app/decision_output.h"

namespace foresight {

std::string DecisionSvg(const DecisionRun& run);

}  // namespace foresight
