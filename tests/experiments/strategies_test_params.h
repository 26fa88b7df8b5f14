// The strategies experiment's settings for tests: the paper's speeds, a short step limit.
#pragma once

#include <utility>

#include "experiments/experiment_params.h"

namespace foresight::testing {

inline StrategiesParams TestStrategiesParams(Situation situation, int starts) {
  StrategiesParams p;
  p.situation = std::move(situation);
  p.strategies = {Strategy::kFast, Strategy::kOptimalValue, Strategy::kOptimalAll,
                  Strategy::kOptimalOne};
  p.starts = starts;
  p.max_steps = 60;
  p.walk_speed_mps = 0.2;
  p.turn_speed_radps = 60.0 * kDegToRad;
  p.turn_around_ball_speed_radps = 30.0 * kDegToRad;
  p.Validate();
  return p;
}

}  // namespace foresight::testing
