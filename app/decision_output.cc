#include "app/decision_output.h"

namespace foresight {

std::string KickName(const DecisionRun& run, int kick_index) {
  return run.planner->situation().kicks.NameOf(kick_index);
}

}  // namespace foresight
