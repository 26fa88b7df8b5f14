#include "app/decision_output.h"

namespace foresight {

std::string KickName(const DecisionRun& run, int kick_index) {
  if (kick_index < 0) return "none";
  return run.planner->situation().kicks.kicks[static_cast<std::size_t>(kick_index)].name;
}

}  // namespace foresight
