// Evaluating a hypothesis, the N simulated outcomes of one action (Mellmann & Schlotter,
// sec. III-D): category shares (eq. 2)
//   p_c = |H_a intersect S_c| / |H_a|,
// utility (eq. 5)
//   u = v_avg * p_infield + v_max * p_goal,  v_avg = mean value of the infield samples,
// and the trimmed utility (eq. 6): 0 when p_out > T_out or any sample is an own goal.
#pragma once

#include <array>

#include "models/evaluation_params.h"
#include "models/outcome.h"

namespace foresight {

// Eq. 5 from the value of the infield samples and the shares; v_max is params.goal_value.
inline double Utility(double value_avg, double p_infield, double p_opp_goal,
                      const EvaluationParams& params) {
  return value_avg * p_infield + params.goal_value * p_opp_goal;
}

// Eq. 5 for one outcome (a hypothesis of one sample): the rest position's value `value` when
// infield, v_max for an opponent goal, 0 otherwise. Its mean over a hypothesis is the
// hypothesis's utility; physics reports use it per trial for intervals.
inline double OutcomeUtility(Category category, double value, const EvaluationParams& params) {
  const bool infield = category == Category::kInfield;
  return Utility(infield ? value : 0.0, infield ? 1.0 : 0.0,
                 category == Category::kOppGoal ? 1.0 : 0.0, params);
}

struct ActionEvaluation {
  int samples = 0;
  std::array<int, kCategoryCount> counts{};  // indexed by Category
  double p_infield = 0.0;
  double p_opp_goal = 0.0;
  double p_own_goal = 0.0;
  double p_out = 0.0;
  double value_avg = 0.0;          // v_avg over the infield samples (0 when there are none)
  double potential_avg = 0.0;      // mean potential of the infield samples (NaoTH rule, step 3)
  double potential_all_avg = 0.0;  // mean potential of every sample's rest position, goal and
                                   // out samples included (NaoTH rule: ties on goal samples)
  double utility = 0.0;            // eq. 5
  double trimmed_utility = 0.0;    // eq. 6
  bool too_risky = false;          // trimmed: p_out > T_out or an own goal

  int Count(Category c) const { return counts[static_cast<int>(c)]; }
};

// The most samples of N that may be out without trimming the hypothesis: floor(T_out * N).
int MaxOuts(const EvaluationParams& params, int samples);

// Eq. 6's trimming, the one definition: an own goal, or more than MaxOuts(N) of a hypothesis's
// N samples out (p_out > T_out). The outs counted may be those of its first samples only: a
// hypothesis is then trimmed when it is whatever its other samples do.
inline bool Trimmed(int outs, int own_goals, int max_outs) {
  return outs > max_outs || own_goals > 0;
}

// Sums the samples of one hypothesis; Finish() turns the sums into an ActionEvaluation.
// `potential` is the potential at the sample's rest position whatever its category; `value`
// counts only for infield samples.
//
// Each sum is kept as kSumSlots strided partial sums: the i-th sample added (from 0) goes to slot
// i mod 8, each slot sums its samples in the order they come, from +0.0, and Finish adds the slots
// pairwise, ((s0 + s1) + (s2 + s3)) + ((s4 + s5) + (s6 + s7)). One fixed order of additions, so
// SIMD lanes of any width (2, 4 or 8: 4, 2 or 1 vectors of slots, FromSlots) give exactly the
// bits of Add sample by sample, and no sum is a chain of one dependent addition per sample.
class HypothesisAccumulator {
 public:
  static constexpr int kSumSlots = 8;

  void Add(Category category, double value, double potential) {
    const int slot = added_ % kSumSlots;
    ++added_;
    ++counts_[static_cast<int>(category)];
    potential_all_sum_[slot] += potential;
    // Without a branch (the category is a coin toss for the predictor): adding +0.0 leaves these
    // sums' bits unchanged, as a sum that starts at +0.0 is never -0.0 (round to nearest).
    const bool infield = category == Category::kInfield;
    value_sum_[slot] += infield ? value : 0.0;
    potential_sum_[slot] += infield ? potential : 0.0;
  }
  // The accumulator of a hypothesis's first samples from their counts and slot sums, as Add
  // would have summed them (the slots of `value` and `infield_potential` hold +0.0 for samples
  // that are not infield): for callers that sum in SIMD lanes.
  static HypothesisAccumulator FromSlots(const std::array<int, kCategoryCount>& counts,
                                         const double* value, const double* infield_potential,
                                         const double* potential) {
    HypothesisAccumulator h;
    h.counts_ = counts;
    h.added_ = h.Samples();
    for (int s = 0; s < kSumSlots; ++s) {
      h.value_sum_[s] = value[s];
      h.potential_sum_[s] = infield_potential[s];
      h.potential_all_sum_[s] = potential[s];
    }
    return h;
  }

  // The evaluation of the samples added, trimmed as eq. 6 trims a hypothesis of
  // `hypothesis_samples` samples (N) of which these are the first n: the utility of those n,
  // trimmed only when the whole hypothesis is certain to be, whatever its other samples do
  // (Trimmed with MaxOuts(params, N)). A look at fewer samples then never trims an action that
  // all N would keep: with 10 of 30 samples 2 outs would trim (p_out = 0.2 > 0.15), 4 of 30 do
  // not. With all N added it is eq. 6 itself.
  ActionEvaluation Finish(const EvaluationParams& params, int hypothesis_samples) const;
  // A hypothesis of the samples added.
  ActionEvaluation Finish(const EvaluationParams& params) const {
    return Finish(params, Samples());
  }
  int Samples() const {
    int n = 0;
    for (int c : counts_) n += c;
    return n;
  }

  // True once the hypothesis is trimmed whatever its remaining samples do: more than
  // `max_outs` samples out (max_outs = floor(T_out * N)) or an own goal.
  bool CertainlyTrimmed(int max_outs) const {
    return Trimmed(counts_[static_cast<int>(Category::kOut)],
                   counts_[static_cast<int>(Category::kOwnGoal)], max_outs);
  }

 private:
  std::array<int, kCategoryCount> counts_{};
  int added_ = 0;
  double value_sum_[kSumSlots] = {};
  double potential_sum_[kSumSlots] = {};
  double potential_all_sum_[kSumSlots] = {};
};

}  // namespace foresight
