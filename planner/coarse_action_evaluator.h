// The decision's hot path: the coarse model evaluated without the seam's per-sample work.
//
// A candidate is (kick k, rotation rho); sample i launches the ball from p_i at speed v_ik in
// direction theta_i + rho + alpha_ik. Everything but rho is fixed for the whole decision, so
// the unit vectors u_ik = (cos, sin)(theta_i + alpha_ik), the speeds, the stop distances and the
// start's category are computed once, and a candidate costs one rotation of u_ik by rho per
// sample instead of a sine and cosine. The samples are drawn, rolled, classified and valued
// kLanes at a time in SIMD lanes (planner/sampling.h, planner/roll_lanes.h,
// PositionValue::PotentialLanes) and summed in HypothesisAccumulator's slots (sample i in slot
// i mod 8, each slot in sample order), so an evaluation has the bits of
// the scalar reference (EvaluateReference: one RollBall per sample, tested equal) and equals
// SeamActionEvaluator's over a CoarseSimulator up to rounding (tested).
//
// Storage is kept between decisions: Redraw draws the samples for another state and seed into
// the same buffers, so a thread deciding with one evaluator never allocates once the buffers
// hold its sample count.
#pragma once

#include <cstdint>
#include <vector>

#include "planner/action_evaluator.h"
#include "planner/coarse_world.h"
#include "planner/roll_lanes.h"

namespace foresight {

class CoarseActionEvaluator final : public ActionEvaluator {
 public:
  // Samples are drawn from `state` (the situation's static parts apply).
  CoarseActionEvaluator(const Situation& situation, const StateEstimate& state,
                        const CoarseWorld& world, const PositionValue& value, int samples,
                        std::uint64_t seed);

  // Draws `samples` samples of `state` with `seed` into this evaluator's storage (allocating
  // only when it has never held that many).
  void Redraw(const StateEstimate& state, int samples, std::uint64_t seed);

  ActionEvaluation Evaluate(int kick_index, double rotation_rad) override {
    return Run(kick_index, rotation_rad, sample_count_, false);
  }
  ActionEvaluation EvaluateFirst(int kick_index, double rotation_rad, int samples) override {
    return Run(kick_index, rotation_rad, samples, false);
  }
  ActionEvaluation EvaluateForSearch(int kick_index, double rotation_rad, int samples) override {
    return Run(kick_index, rotation_rad, samples, true);
  }
  std::vector<Outcome> Outcomes(int kick_index, double rotation_rad) const override;

  // The scalar reference of Evaluate: one RollBall per sample (for tests).
  ActionEvaluation EvaluateReference(int kick_index, double rotation_rad) const;

  int sample_count() const override { return sample_count_; }

 private:
  // The first `samples` samples (at most all).
  ActionEvaluation Run(int kick_index, double rotation_rad, int samples, bool stop_when_trimmed);
  // Lanes first .. first + kLanes - 1: the launch of a kick turned by rho, or the ball at rest.
  RollLanesInput Launch(int kick_index, std::size_t first, double cos_rho, double sin_rho) const;
  RestLanes RestingLanes(std::size_t first) const;
  Outcome SimulateOne(int kick_index, std::size_t sample, double cos_rho, double sin_rho) const;
  std::size_t LaunchSlot(int kick_index, std::size_t sample) const {
    return static_cast<std::size_t>(kick_index) * padded_count_ + sample;
  }

  const CoarseWorld& world_;
  const PositionValue& value_;
  int sample_count_ = 0;
  std::size_t padded_count_ = 0;  // sample_count_ rounded up to whole lanes
  // Per sample (padded): the ball and the category of its start.
  std::vector<double> ball_x_, ball_y_;
  std::vector<std::int64_t> start_category_;
  // Per kick, then per sample (padded), [LaunchSlot(kick, i)]: the launch before the turn.
  std::vector<double> direction_x_, direction_y_, speed_mps_, stop_m_;
  std::vector<std::int64_t> moving_;  // -1 when the launch speed is > 0 (lane mask)
};

}  // namespace foresight
