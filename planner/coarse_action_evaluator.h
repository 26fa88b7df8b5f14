// The decision's hot path: the coarse model evaluated without the seam's per-sample work.
//
// A candidate is (kick k, rotation rho); sample i launches the ball from p_i at speed v_ik in
// direction theta_i + rho + alpha_ik. Everything but rho is fixed for the whole decision, so
// the unit vectors u_ik = (cos, sin)(theta_i + alpha_ik) and the speeds are computed once, and
// a candidate costs one rotation of u_ik by rho per sample instead of a sine and cosine.
// Answers equal SeamActionEvaluator's over a CoarseSimulator up to rounding (tested).
#pragma once

#include <cstdint>
#include <vector>

#include "planner/action_evaluator.h"
#include "planner/coarse_world.h"

namespace foresight {

class CoarseActionEvaluator final : public ActionEvaluator {
 public:
  // Samples are drawn from `state` (the situation's static parts apply).
  CoarseActionEvaluator(const Situation& situation, const StateEstimate& state,
                        const CoarseWorld& world, const PositionValue& value, int samples,
                        std::uint64_t seed);

  ActionEvaluation Evaluate(int kick_index, double rotation_rad) override {
    return Run(kick_index, rotation_rad, false);
  }
  ActionEvaluation EvaluateForSearch(int kick_index, double rotation_rad) override {
    return Run(kick_index, rotation_rad, true);
  }
  std::vector<Outcome> Outcomes(int kick_index, double rotation_rad) const override;

 private:
  struct Launch {
    Vec2 direction_F{1.0, 0.0};  // before the rotation around the ball
    double speed_mps = 0.0;
  };

  ActionEvaluation Run(int kick_index, double rotation_rad, bool stop_when_trimmed);
  Outcome SimulateOne(int kick_index, std::size_t sample, double cos_rho, double sin_rho) const;

  const CoarseWorld& world_;
  const PositionValue& value_;
  int sample_count_ = 0;
  std::vector<Vec2> p_F_ball_;    // per sample
  std::vector<Launch> launches_;  // per kick, then per sample: [kick * samples + i]
};

}  // namespace foresight
