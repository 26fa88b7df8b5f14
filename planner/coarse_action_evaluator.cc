#include "planner/coarse_action_evaluator.h"

#include <cmath>

#include "planner/ball_roll.h"

namespace foresight {

CoarseActionEvaluator::CoarseActionEvaluator(const Situation& situation, const StateEstimate& state,
                                             const CoarseWorld& world, const PositionValue& value,
                                             int samples, std::uint64_t seed)
    : ActionEvaluator(situation, state), world_(world), value_(value), sample_count_(samples) {
  std::vector<DrawnSample> drawn;
  DrawSamples(state, seed, samples, drawn);
  p_F_ball_.reserve(drawn.size());
  for (const DrawnSample& d : drawn) p_F_ball_.push_back(d.state.p_F_ball);
  launches_.resize(static_cast<std::size_t>(kick_count()) * drawn.size());
  for (int k = 0; k < kick_count(); ++k) {
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      const ConcreteAction a = MakeAction(situation.kicks, k, 0.0, drawn[i]);
      launches_[k * drawn.size() + i] = {
          UnitVector(drawn[i].state.robot.theta_rad + a.launch_direction_rad), a.launch_speed_mps};
    }
  }
}

Outcome CoarseActionEvaluator::SimulateOne(int kick_index, std::size_t sample, double cos_rho,
                                           double sin_rho) const {
  if (kick_index == kNoKick) return RollBall(world_, p_F_ball_[sample], Vec2(1.0, 0.0), 0.0);
  const Launch& launch =
      launches_[static_cast<std::size_t>(kick_index) * p_F_ball_.size() + sample];
  const Vec2& u = launch.direction_F;
  const Vec2 direction(cos_rho * u.x() - sin_rho * u.y(), sin_rho * u.x() + cos_rho * u.y());
  return RollBall(world_, p_F_ball_[sample], direction, launch.speed_mps);
}

ActionEvaluation CoarseActionEvaluator::Run(int kick_index, double rotation_rad,
                                            bool stop_when_trimmed) {
  ++evaluations_;
  double sin_rho, cos_rho;
  SinCos(rotation_rad, &sin_rho, &cos_rho);
  const EvaluationParams& params = situation_.evaluation;
  // More outs than this, or one own goal, trims the action whatever the other samples do.
  const int max_outs = static_cast<int>(std::floor(params.max_out_share * sample_count_ + 1e-9));
  HypothesisAccumulator hypothesis;
  for (std::size_t i = 0; i < p_F_ball_.size(); ++i) {
    const Outcome outcome = SimulateOne(kick_index, i, cos_rho, sin_rho);
    AddOutcome(hypothesis, outcome, value_);
    if (stop_when_trimmed && hypothesis.CertainlyTrimmed(max_outs)) {
      ActionEvaluation trimmed = hypothesis.Finish(params);
      trimmed.too_risky = true;
      trimmed.trimmed_utility = 0.0;
      return trimmed;
    }
  }
  return hypothesis.Finish(params);
}

std::vector<Outcome> CoarseActionEvaluator::Outcomes(int kick_index, double rotation_rad) const {
  double sin_rho, cos_rho;
  SinCos(rotation_rad, &sin_rho, &cos_rho);
  std::vector<Outcome> outcomes;
  outcomes.reserve(p_F_ball_.size());
  for (std::size_t i = 0; i < p_F_ball_.size(); ++i) {
    outcomes.push_back(SimulateOne(kick_index, i, cos_rho, sin_rho));
  }
  return outcomes;
}

}  // namespace foresight
