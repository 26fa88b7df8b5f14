#include "planner/strategy_names.h"

#include "common/enum_names.h"

namespace foresight {
namespace {

constexpr EnumNames<Strategy, 5> kStrategyNames{{{
    {Strategy::kFast, "fast"},
    {Strategy::kOptimalValue, "optimal_value"},
    {Strategy::kOptimalAll, "optimal_all"},
    {Strategy::kOptimalOne, "optimal_one"},
    {Strategy::kNaoth, "naoth"},
}}};

}  // namespace

std::string_view StrategyName(Strategy strategy) {
  return kStrategyNames.Name(strategy);
}
std::optional<Strategy> ParseStrategy(std::string_view name) {
  return kStrategyNames.Parse(name);
}
std::vector<Strategy> AllStrategies() {
  return kStrategyNames.All();
}
std::string StrategyNames() {
  return kStrategyNames.List();
}

}  // namespace foresight
