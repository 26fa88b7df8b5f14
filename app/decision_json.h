// `foresight decide --json`: the decision and every kick's evaluation (the contract).
#pragma once

#include <nlohmann/json.hpp>

#include "app/decision_output.h"

namespace foresight {

nlohmann::ordered_json DecisionJson(const DecisionRun& run);

}  // namespace foresight
