// The decision's fast evaluator against the generic one through the outcome-simulator seam:
// two implementations of the same hypothesis must agree.
#include "planner/coarse_action_evaluator.h"

#include <gtest/gtest.h>

#include "common/random.h"
#include "planner/coarse_planner.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

TEST(CoarseActionEvaluatorTest, AgreesWithTheSeamEvaluator) {
  RandomStream rng(StreamKey(31, 0));
  int compared = 0, category_mismatches = 0;
  for (int trial = 0; trial < 40; ++trial) {
    testing::StateSpec spec;
    do {  // a robot whose ball is clear of the obstacles
      spec = testing::RandomPose(rng, 4.3, 2.9);
    } while ((Vec2(spec.x_m, spec.y_m) - Vec2(3.9, 0.3)).norm() < 0.6 ||
             (Vec2(spec.x_m, spec.y_m) - Vec2(-3.5, -0.5)).norm() < 0.6);
    const Situation s =
        testing::MakeSituation(spec, {{Vec2(3.9, 0.3), 0.15}, {Vec2(-3.5, -0.5), 0.2}});
    const CoarsePlanner planner(s);
    CoarseActionEvaluator fast = planner.MakeEvaluator(30, trial);
    SeamActionEvaluator seam = planner.MakeSeamEvaluator(30, trial);
    for (int kick = -1; kick < 3; ++kick) {
      const double rho = 2.0 * kPi * rng.NextUniform() - kPi;
      const std::vector<Outcome> a = fast.Outcomes(kick, rho), b = seam.Outcomes(kick, rho);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t i = 0; i < a.size(); ++i) {
        // The fast path rotates a precomputed direction; rounding differs in the last bits.
        EXPECT_NEAR((a[i].p_F_rest - b[i].p_F_rest).norm(), 0.0, 1e-9);
        EXPECT_NEAR(a[i].time_s, b[i].time_s, 1e-9);
        category_mismatches += a[i].category != b[i].category;
        ++compared;
      }
      const ActionEvaluation ea = fast.Evaluate(kick, rho), eb = seam.Evaluate(kick, rho);
      EXPECT_NEAR(ea.utility, eb.utility, 1e-9);
    }
  }
  EXPECT_EQ(compared, 40 * 4 * 30);
  EXPECT_EQ(category_mismatches, 0);
}

TEST(CoarseActionEvaluatorTest, SearchEvaluationStopsOnlyWhenCertainlyTrimmed) {
  // On the side line the left side kick sends the ball out: the search may stop early, but
  // its verdict equals the full evaluation's.
  const Situation s = testing::MakeSituation(testing::Uncertain({.x_m = 0.5, .y_m = 2.75}));
  const CoarsePlanner planner(s);
  CoarseActionEvaluator evaluator = planner.MakeEvaluator(30, 1);
  for (int kick = 0; kick < 3; ++kick) {
    for (double deg = -180; deg < 180; deg += 15) {
      const ActionEvaluation full = evaluator.Evaluate(kick, deg * kDegToRad);
      const ActionEvaluation search = evaluator.EvaluateForSearch(kick, deg * kDegToRad);
      EXPECT_EQ(full.too_risky, search.too_risky);
      EXPECT_EQ(full.trimmed_utility, search.trimmed_utility);
    }
  }
  const ActionEvaluation partial = evaluator.EvaluateForSearch(1, 0.0);
  EXPECT_TRUE(partial.too_risky);
  EXPECT_LT(partial.samples, 30);  // it did stop early
}

}  // namespace
}  // namespace foresight
