// Category shares, utility (eq. 5) and trimming (eq. 6) on hand-made hypotheses.
#include "planner/hypothesis.h"

#include <array>

#include <gtest/gtest.h>

#include "tests/support/test_situations.h"

namespace foresight {
namespace {

EvaluationParams Params() {
  return testing::MakeSituation({}).evaluation;
}

ActionEvaluation Make(int infield, double value_each, int goal, int own, int out) {
  HypothesisAccumulator h;
  for (int i = 0; i < infield; ++i) h.Add(Category::kInfield, value_each, -value_each);
  for (int i = 0; i < goal; ++i) h.Add(Category::kOppGoal, 0.0, 0.0);
  for (int i = 0; i < own; ++i) h.Add(Category::kOwnGoal, 0.0, 0.0);
  for (int i = 0; i < out; ++i) h.Add(Category::kOut, 0.0, 0.0);
  return h.Finish(Params());
}

TEST(HypothesisTest, UtilityIsValueTimesInfieldPlusGoalShare) {
  const ActionEvaluation e = Make(20, 0.6, 8, 0, 2);  // 30 samples
  EXPECT_DOUBLE_EQ(e.p_infield, 20.0 / 30);
  EXPECT_DOUBLE_EQ(e.p_opp_goal, 8.0 / 30);
  EXPECT_DOUBLE_EQ(e.p_out, 2.0 / 30);
  EXPECT_DOUBLE_EQ(e.value_avg, 0.6);
  EXPECT_DOUBLE_EQ(e.utility, 0.6 * 20.0 / 30 + 1.0 * 8.0 / 30);
  EXPECT_FALSE(e.too_risky);
  EXPECT_DOUBLE_EQ(e.trimmed_utility, e.utility);
}

TEST(HypothesisTest, FirstSamplesAreTrimmedOnlyWhenAllWouldBe) {
  // 2 outs in the first 10 of 30 samples: a share of 0.2 > T_out, but all 30 may still hold
  // only 4 (0.133): not trimmed. 5 outs, or an own goal, trim all 30 whatever the rest do.
  const EvaluationParams params = Params();
  const int max_outs = MaxOuts(params, 30);
  EXPECT_EQ(max_outs, 4);
  const auto first = [&](int infield, int own, int out) {
    HypothesisAccumulator h;
    for (int i = 0; i < infield; ++i) h.Add(Category::kInfield, 0.5, -0.5);
    for (int i = 0; i < own; ++i) h.Add(Category::kOwnGoal, 0.0, 0.0);
    for (int i = 0; i < out; ++i) h.Add(Category::kOut, 0.0, 0.0);
    return h.Finish(params, 30);
  };
  const ActionEvaluation two_out = first(8, 0, 2);
  EXPECT_FALSE(two_out.too_risky);
  EXPECT_DOUBLE_EQ(two_out.trimmed_utility, 0.5 * 8.0 / 10);
  EXPECT_EQ(two_out.samples, 10);
  EXPECT_TRUE(first(5, 0, 5).too_risky);
  EXPECT_EQ(first(5, 0, 5).trimmed_utility, 0.0);
  EXPECT_TRUE(first(9, 1, 0).too_risky);
  // With all samples it is Finish's verdict.
  EXPECT_FALSE(Make(26, 0.5, 0, 0, 4).too_risky);
}

TEST(HypothesisTest, TrimmedWhenOutShareExceedsThreshold) {
  // T_out = 0.15: 4 of 30 (0.133) is acceptable, 5 of 30 (0.167) is not.
  EXPECT_FALSE(Make(26, 0.5, 0, 0, 4).too_risky);
  const ActionEvaluation risky = Make(25, 0.5, 0, 0, 5);
  EXPECT_TRUE(risky.too_risky);
  EXPECT_EQ(risky.trimmed_utility, 0.0);
  EXPECT_GT(risky.utility, 0.0);
}

TEST(HypothesisTest, OneOwnGoalSampleTrimsEvenAGreatKick) {
  const ActionEvaluation e = Make(0, 0.0, 29, 1, 0);
  EXPECT_TRUE(e.too_risky);
  EXPECT_EQ(e.trimmed_utility, 0.0);
}

TEST(HypothesisTest, AllInGoalIsWorthTheGoalValue) {
  const ActionEvaluation e = Make(0, 0.0, 30, 0, 0);
  EXPECT_DOUBLE_EQ(e.utility, Params().goal_value);
  EXPECT_EQ(e.value_avg, 0.0);
}

TEST(HypothesisTest, PotentialMeansOverInfieldAndOverAllSamples) {
  HypothesisAccumulator h;
  h.Add(Category::kInfield, 0.5, -1.0);
  h.Add(Category::kInfield, 0.7, -2.0);
  h.Add(Category::kOppGoal, 0.0, -3.0);
  h.Add(Category::kOut, 0.0, 2.0);
  const ActionEvaluation e = h.Finish(Params());
  EXPECT_DOUBLE_EQ(e.potential_avg, -1.5);            // infield only
  EXPECT_DOUBLE_EQ(e.potential_all_avg, -4.0 / 4.0);  // every sample
}

TEST(HypothesisTest, OutcomeUtilityIsEq5ForOneSample) {
  const EvaluationParams p = Params();
  EXPECT_EQ(OutcomeUtility(Category::kInfield, 0.37, p), 0.37);
  EXPECT_EQ(OutcomeUtility(Category::kOppGoal, 0.37, p), p.goal_value);
  EXPECT_EQ(OutcomeUtility(Category::kOut, 0.37, p), 0.0);
  EXPECT_EQ(OutcomeUtility(Category::kOwnGoal, 0.37, p), 0.0);
  // Its mean over a hypothesis is the hypothesis's utility.
  const ActionEvaluation e = Make(2, 0.5, 1, 0, 1);
  const double mean = (2 * OutcomeUtility(Category::kInfield, 0.5, p) +
                       OutcomeUtility(Category::kOppGoal, 0.0, p)) /
                      4.0;
  EXPECT_DOUBLE_EQ(e.utility, mean);
}

TEST(HypothesisTest, SlotSumsGiveTheBitsOfAddSampleBySample) {
  // 37 samples (not a multiple of 8) with values whose sum depends on the order of additions:
  // FromSlots with slot s summing samples s, s + 8, ... in order is Add's accumulator exactly,
  // and the slots' order differs from one running sum in the last bits.
  const EvaluationParams params = Params();
  HypothesisAccumulator added;
  double value[8] = {}, infield_potential[8] = {}, potential[8] = {};
  std::array<int, kCategoryCount> counts{};
  double running = 0.0;
  for (int i = 0; i < 37; ++i) {
    const Category c = i % 5 == 3 ? Category::kOppGoal : Category::kInfield;
    const double v = 1.0 / (3 + i), f = (i % 2 == 0 ? 1e8 : -1e8) + 1.0 / (7 + i);
    added.Add(c, v, f);
    const bool infield = c == Category::kInfield;
    value[i % 8] += infield ? v : 0.0;
    infield_potential[i % 8] += infield ? f : 0.0;
    potential[i % 8] += f;
    running += f;
    ++counts[static_cast<int>(c)];
  }
  const ActionEvaluation a = added.Finish(params, 37);
  const ActionEvaluation b = HypothesisAccumulator::FromSlots(counts, value, infield_potential,
                                                              potential)
                                 .Finish(params, 37);
  EXPECT_EQ(a.counts, b.counts);
  EXPECT_EQ(a.value_avg, b.value_avg);
  EXPECT_EQ(a.potential_avg, b.potential_avg);
  EXPECT_EQ(a.potential_all_avg, b.potential_all_avg);
  EXPECT_EQ(a.utility, b.utility);
  const double slots = ((potential[0] + potential[1]) + (potential[2] + potential[3])) +
                       ((potential[4] + potential[5]) + (potential[6] + potential[7]));
  EXPECT_EQ(a.potential_all_avg, slots / 37);
  EXPECT_NE(slots, running);  // the order is the slots', not one running sum's
}

}  // namespace
}  // namespace foresight
