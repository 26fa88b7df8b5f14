#include "planner/strategy_names.h"

namespace foresight {

std::string_view StrategyName(Strategy strategy) {
  switch (strategy) {
    case Strategy::kFast:
      return "fast";
    case Strategy::kOptimalValue:
      return "optimal_value";
    case Strategy::kOptimalAll:
      return "optimal_all";
    case Strategy::kOptimalOne:
      return "optimal_one";
    case Strategy::kNaoth:
      return "naoth";
  }
  return "?";
}

std::vector<Strategy> AllStrategies() {
  return {Strategy::kFast, Strategy::kOptimalValue, Strategy::kOptimalAll, Strategy::kOptimalOne,
          Strategy::kNaoth};
}

std::string StrategyNames() {
  std::string names;
  for (Strategy s : AllStrategies())
    names += (names.empty() ? "" : ", ") + std::string(StrategyName(s));
  return names;
}

std::optional<Strategy> ParseStrategy(std::string_view name) {
  for (Strategy s : AllStrategies()) {
    if (StrategyName(s) == name) return s;
  }
  return std::nullopt;
}

}  // namespace foresight
