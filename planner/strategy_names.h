// The decision strategies of Mellmann & Schlotter, sec. IV-A (planner/decision.h describes
// them), and their names as the command line, the JSON and the reports spell them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace foresight {

enum class Strategy { kFast, kOptimalValue, kOptimalAll, kOptimalOne, kNaoth };

std::string_view StrategyName(Strategy strategy);
std::optional<Strategy> ParseStrategy(std::string_view name);
std::vector<Strategy> AllStrategies();
std::string StrategyNames();  // "fast, optimal_value, ..." for help texts and messages

}  // namespace foresight
