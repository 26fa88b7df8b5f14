// The decision's fast evaluator against the generic one through the outcome-simulator seam:
// two implementations of the same hypothesis must agree.
#include "planner/coarse_action_evaluator.h"

#include <gtest/gtest.h>

#include "common/random.h"
#include "models/physics_params.h"
#include "planner/coarse_planner.h"
#include "tests/support/temp_files.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

// The coarse model's variants: the paper's (no rebounds, no launch offset), and rebounds with the
// shipped restitution plus launch offsets on two kicks.
enum class Variant { kPaper, kReboundsAndOffsets };

Situation Configure(Situation s, Variant variant) {
  if (variant == Variant::kReboundsAndOffsets) {
    const BallPairs e =
        LoadPhysicsParams(testing::ModelsDir() / "physics" / "spl.json").materials.restitution;
    s.evaluation.rebounds = {true, 8, e.post, e.net, e.robot};
    s.kicks.kicks[0].launch_offset_m = 0.06;
    s.kicks.kicks[2].launch_offset_m = 0.02;
  }
  return s;
}

class CoarseVariantTest : public ::testing::TestWithParam<Variant> {};

INSTANTIATE_TEST_SUITE_P(Variants, CoarseVariantTest,
                         ::testing::Values(Variant::kPaper, Variant::kReboundsAndOffsets));

TEST_P(CoarseVariantTest, AgreesWithTheSeamEvaluator) {
  RandomStream rng(StreamKey(31, 0));
  int compared = 0, category_mismatches = 0;
  for (int trial = 0; trial < 40; ++trial) {
    testing::StateSpec spec;
    do {  // a robot whose ball is clear of the obstacles
      spec = testing::RandomPose(rng, 4.3, 2.9);
    } while ((Vec2(spec.x_m, spec.y_m) - Vec2(3.9, 0.3)).norm() < 0.6 ||
             (Vec2(spec.x_m, spec.y_m) - Vec2(-3.5, -0.5)).norm() < 0.6);
    const Situation s =
        Configure(testing::MakeSituation(spec, {{Vec2(3.9, 0.3), 0.15}, {Vec2(-3.5, -0.5), 0.2}}),
                  GetParam());
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
        // A ball that barely reaches a contact arrives at v_hit near 0, where the time to it,
        // (v0 - v_hit) / a, moves by ds / v_hit: rebounds then carry that rounding on.
        EXPECT_NEAR(a[i].time_s, b[i].time_s, GetParam() == Variant::kPaper ? 1e-9 : 1e-6);
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

// The SIMD lanes against the scalar reference (one RollBall per sample): the same operations in
// the same order, so the same bits, over random poses all over the field (posts, nets,
// obstacles, lines), random turns and sample counts that leave partly filled lanes.
TEST_P(CoarseVariantTest, LanesGiveTheScalarReferenceBits) {
  RandomStream rng(StreamKey(47, 0));
  int goals = 0, outs = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Situation s =
        Configure(testing::MakeSituation(testing::RandomPose(rng, 4.6, 3.1),
                                         {{Vec2(3.9, 0.3), 0.15}, {Vec2(-1.0, 1.0), 0.2}}),
                  GetParam());
    const CoarsePlanner planner(s);
    const int samples = 1 + trial % 37;
    CoarseActionEvaluator evaluator = planner.MakeEvaluator(samples, trial);
    for (int kick = 0; kick < 3; ++kick) {
      for (int turn = 0; turn < 8; ++turn) {
        const double rho = 2.0 * kPi * rng.NextUniform() - kPi;
        const ActionEvaluation lanes = evaluator.Evaluate(kick, rho);
        const ActionEvaluation reference = evaluator.EvaluateReference(kick, rho);
        EXPECT_EQ(lanes.counts, reference.counts);
        EXPECT_EQ(lanes.value_avg, reference.value_avg);  // bitwise
        EXPECT_EQ(lanes.potential_avg, reference.potential_avg);
        EXPECT_EQ(lanes.potential_all_avg, reference.potential_all_avg);
        EXPECT_EQ(lanes.utility, reference.utility);
        goals += lanes.Count(Category::kOppGoal) + lanes.Count(Category::kOwnGoal);
        outs += lanes.Count(Category::kOut);
      }
    }
  }
  EXPECT_GT(goals, 100);  // the poses do reach the goals and the lines
  EXPECT_GT(outs, 100);
}

// The same near the posts, where most samples rebound (several times, off posts and nets).
TEST_P(CoarseVariantTest, LanesGiveTheScalarReferenceBitsNearThePosts) {
  RandomStream rng(StreamKey(53, 0));
  int contacts = 0;
  for (int trial = 0; trial < 40; ++trial) {
    testing::StateSpec spec = testing::RandomPose(rng, 0.6, 1.2);
    spec.x_m += (trial % 2 == 0 ? 3.7 : -3.7);
    spec.theta_deg = trial % 2 == 0 ? spec.theta_deg / 4.0 : 180.0 + spec.theta_deg / 4.0;
    const Situation s =
        Configure(testing::MakeSituation(spec, {{Vec2(3.0, -1.0), 0.15}}), GetParam());
    const CoarsePlanner planner(s);
    const int samples = 1 + trial % 23;
    CoarseActionEvaluator evaluator = planner.MakeEvaluator(samples, trial);
    for (int kick = 0; kick < 3; ++kick) {
      for (int turn = 0; turn < 8; ++turn) {
        const double rho = 0.5 * (rng.NextUniform() - 0.5);
        const ActionEvaluation lanes = evaluator.Evaluate(kick, rho);
        const ActionEvaluation reference = evaluator.EvaluateReference(kick, rho);
        EXPECT_EQ(lanes.counts, reference.counts);
        EXPECT_EQ(lanes.value_avg, reference.value_avg);  // bitwise
        EXPECT_EQ(lanes.potential_all_avg, reference.potential_all_avg);
        EXPECT_EQ(lanes.utility, reference.utility);
        for (const Outcome& o : evaluator.Outcomes(kick, rho)) {
          contacts += o.first_contact != Contact::kNone;
        }
      }
    }
  }
  EXPECT_GT(contacts, 300);  // the kicks do meet posts and nets
}

// An evaluator redrawn for another state and seed equals one made for them.
TEST(CoarseActionEvaluatorTest, RedrawEqualsAFreshEvaluator) {
  const Situation s = testing::MakeSituation(testing::Uncertain({.x_m = 1.0, .y_m = 0.5}));
  const CoarsePlanner planner(s);
  CoarseActionEvaluator reused = planner.MakeEvaluator(40, 3);
  StateEstimate other = s.state;
  other.robot = Pose2{Vec2(3.5, -1.5), 0.7};
  reused.Redraw(other, 17, 11);
  CoarseActionEvaluator fresh = planner.MakeEvaluator(other, 17, 11);
  for (int kick = -1; kick < 3; ++kick) {
    const ActionEvaluation a = reused.Evaluate(kick, 0.3), b = fresh.Evaluate(kick, 0.3);
    EXPECT_EQ(a.counts, b.counts);
    EXPECT_EQ(a.utility, b.utility);
    EXPECT_EQ(a.potential_all_avg, b.potential_all_avg);
  }
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
      const ActionEvaluation search = evaluator.EvaluateForSearch(kick, deg * kDegToRad, 30);
      EXPECT_EQ(full.too_risky, search.too_risky);
      EXPECT_EQ(full.trimmed_utility, search.trimmed_utility);
    }
  }
  const ActionEvaluation partial = evaluator.EvaluateForSearch(1, 0.0, 30);
  EXPECT_TRUE(partial.too_risky);
  EXPECT_LT(partial.samples, 30);  // it did stop early
}

TEST(CoarseActionEvaluatorTest, FirstSamplesAreThoseOfAnEvaluatorWithFewer) {
  // The samples are drawn per index from the seed, so the first 8 of 30 are an evaluator's 8:
  // the same counts and utility, only the trimming is the 30 samples' (certain trims only).
  const Situation s = testing::MakeSituation(testing::Uncertain({.x_m = 2.5, .y_m = 1.9}));
  const CoarsePlanner planner(s);
  CoarseActionEvaluator all = planner.MakeEvaluator(30, 4);
  CoarseActionEvaluator few = planner.MakeEvaluator(8, 4);
  SeamActionEvaluator seam = planner.MakeSeamEvaluator(30, 4);
  int differently_trimmed = 0;
  for (int kick = -1; kick < 3; ++kick) {
    for (double deg = -180; deg < 180; deg += 10) {
      const double rho = deg * kDegToRad;
      const ActionEvaluation first = all.EvaluateFirst(kick, rho, 8);
      const ActionEvaluation alone = few.Evaluate(kick, rho);
      EXPECT_EQ(first.counts, alone.counts);
      EXPECT_EQ(first.utility, alone.utility);
      EXPECT_EQ(first.potential_all_avg, alone.potential_all_avg);
      const bool certain = first.Count(Category::kOwnGoal) > 0 || first.Count(Category::kOut) > 4;
      EXPECT_EQ(first.too_risky, certain);
      differently_trimmed += first.too_risky != alone.too_risky;
      const ActionEvaluation through_seam = seam.EvaluateFirst(kick, rho, 8);
      EXPECT_EQ(first.counts, through_seam.counts);
      EXPECT_NEAR(first.utility, through_seam.utility, 1e-12);
      EXPECT_EQ(first.too_risky, through_seam.too_risky);
      const ActionEvaluation whole = all.EvaluateFirst(kick, rho, 30);
      EXPECT_EQ(whole.utility, all.Evaluate(kick, rho).utility);
      EXPECT_EQ(whole.too_risky, all.Evaluate(kick, rho).too_risky);
    }
  }
  EXPECT_GT(differently_trimmed, 0);  // the pose has candidates with 2-4 outs in 8 samples
}

}  // namespace
}  // namespace foresight
