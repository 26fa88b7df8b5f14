// `foresight decide`'s text: the decision, then one table row per kick and `none`.
#pragma once

#include <string>

#include "app/decision_output.h"

namespace foresight {

std::string DecisionText(const DecisionRun& run);

}  // namespace foresight
