#include "planner/hypothesis.h"

#include <cmath>

namespace foresight {
namespace {

// The slots' total in HypothesisAccumulator's fixed order.
double SlotTotal(const double* s) {
  static_assert(HypothesisAccumulator::kSumSlots == 8);
  return ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
}

}  // namespace

int MaxOuts(const EvaluationParams& params, int samples) {
  // The tolerance keeps T_out * N that should be whole from rounding down.
  return static_cast<int>(std::floor(params.max_out_share * samples + 1e-9));
}

ActionEvaluation HypothesisAccumulator::Finish(const EvaluationParams& params,
                                              int hypothesis_samples) const {
  ActionEvaluation e;
  e.counts = counts_;
  e.samples = Samples();
  if (e.samples == 0) return e;
  const double n = e.samples;
  e.potential_all_avg = SlotTotal(potential_all_sum_) / n;
  e.p_infield = e.Count(Category::kInfield) / n;
  e.p_opp_goal = e.Count(Category::kOppGoal) / n;
  e.p_own_goal = e.Count(Category::kOwnGoal) / n;
  e.p_out = e.Count(Category::kOut) / n;
  const int infield = e.Count(Category::kInfield);
  if (infield > 0) {
    e.value_avg = SlotTotal(value_sum_) / infield;
    e.potential_avg = SlotTotal(potential_sum_) / infield;
  }
  e.utility = Utility(e.value_avg, e.p_infield, e.p_opp_goal, params);
  e.too_risky = CertainlyTrimmed(MaxOuts(params, hypothesis_samples));
  e.trimmed_utility = e.too_risky ? 0.0 : e.utility;
  return e;
}

}  // namespace foresight
