// The rotation search: synthetic objectives with known optima, and the real objective checked
// against brute force over the circle.
#include "planner/rotation_search.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/random.h"
#include "planner/coarse_planner.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

RotationSearchParams Params() {
  return testing::MakeSituation({}).evaluation.rotation_search;
}

RotationObjective Synthetic(double (*utility)(double)) {
  return [utility](double rho) {
    ActionEvaluation e;
    e.utility = e.trimmed_utility = utility(rho);
    return e;
  };
}

TEST(RotationSearchTest, FindsASmoothPeakAnywhereOnTheCircle) {
  for (double peak_deg : {-179.0, -123.4, -3.0, 47.5, 178.2}) {
    static double peak;
    peak = peak_deg * kDegToRad;
    const RotationChoice c = BestRotation(
        Synthetic(+[](double rho) { return std::exp(-std::pow(WrapAngle(rho - peak) / 0.3, 2)); }),
        Params());
    EXPECT_NEAR(WrapAngle(c.rotation_rad - peak), 0.0, 0.6 * kDegToRad) << peak_deg;
  }
}

TEST(RotationSearchTest, PlateauGivesTheLeastTurn) {
  // Best value on [30, 80] deg and on [-100, -60] deg: the least turn is +30 deg.
  const RotationChoice c = BestRotation(Synthetic(+[](double rho) {
                                          const double d = rho * kRadToDeg;
                                          if ((d >= 30 && d <= 80) || (d >= -100 && d <= -60))
                                            return 0.9;
                                          return 0.2 + 0.001 * std::abs(d);
                                        }),
                                        Params());
  EXPECT_NEAR(c.rotation_rad * kRadToDeg, 30.0, 0.3);
  EXPECT_DOUBLE_EQ(c.evaluation.trimmed_utility, 0.9);
}

TEST(RotationSearchTest, FlatObjectiveNeedsNoTurn) {
  const RotationChoice c = BestRotation(Synthetic(+[](double) { return 0.5; }), Params());
  EXPECT_EQ(c.rotation_rad, 0.0);
}

// A look at few samples that misleads: it sees a hill top at 60 deg where all samples are
// trimmed (a cliff beside the real top at 100 deg) and puts its second hill's top a grid step
// off. The search climbs the grid on all samples and refines there.
TEST(RotationSearchTest, CoarseLookIsClimbedOnAllSamples) {
  RotationSearchParams params = Params();
  params.coarse_sample_share = 0.25;
  const int samples = 30;
  int looks_at_few = 0;
  const SampledObjective objective = [&](double rho, int n) {
    const double d = rho * kRadToDeg;
    ActionEvaluation e;
    e.samples = n;
    if (n < samples) {
      ++looks_at_few;
      e.utility = std::abs(d - 60.0) < 15.0 ? 0.95 : 0.5 - 0.001 * std::abs(d - 120.0);
    } else {
      e.utility = d > 50.0 && d < 75.0 ? 0.0 : 0.9 - 0.002 * std::abs(d - 101.5);
      e.too_risky = e.utility == 0.0;
    }
    e.trimmed_utility = e.utility;
    return e;
  };
  const RotationChoice c = BestRotation(objective, samples, params);
  EXPECT_NEAR(c.rotation_rad * kRadToDeg, 101.5, 0.7);
  EXPECT_EQ(c.evaluation.samples, samples);  // the chosen utility is all samples'
  EXPECT_EQ(looks_at_few, 18);               // the grid, and nothing else
}

TEST(RotationSearchTest, LeastAcceptableRotationBisectsTheEdge) {
  auto objective = Synthetic(+[](double rho) { return rho * kRadToDeg >= 42.0 ? 1.0 : 0.0; });
  auto ok = [](const ActionEvaluation& e) { return e.trimmed_utility > 0.5; };
  const auto turn = LeastAcceptableRotation(objective, ok, +1.0, Params());
  ASSERT_TRUE(turn.has_value());
  EXPECT_NEAR(turn->rotation_rad * kRadToDeg, 42.0, 0.1);
  EXPECT_GE(turn->rotation_rad * kRadToDeg, 42.0);
  EXPECT_FALSE(LeastAcceptableRotation(objective, ok, -1.0, Params()).has_value());
}

// Against brute force on the real objective (0.25 deg steps over the whole circle). The
// objective has fine structure (v_avg changes with every sample's rest position), so the test
// bounds the utility lost, not the share of exact hits.
TEST(RotationSearchTest, RealObjectiveMatchesBruteForce) {
  RandomStream rng(StreamKey(2024, 0));
  double worst_loss = 0.0, total_loss = 0.0;
  int total = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const testing::StateSpec spec = testing::RandomPose(rng, 4.0, 2.8);
    const Situation s = testing::MakeSituation(spec);
    const CoarsePlanner planner(s);
    for (int kick = 0; kick < 3; ++kick) {
      CoarseActionEvaluator evaluator = planner.MakeEvaluator(30, 7);
      // As a decision searches: the grid on the first samples, the rest on all of them.
      const SampledObjective objective = [&](double rho, int samples) {
        return evaluator.EvaluateForSearch(kick, rho, samples);
      };
      const RotationChoice found = BestRotation(objective, 30, s.evaluation.rotation_search);
      ASSERT_LT(s.evaluation.rotation_search.CoarseSamples(30), 30);
      double brute = 0.0;
      for (double d = -180.0; d < 180.0; d += 0.25) {
        brute = std::max(brute, evaluator.Evaluate(kick, d * kDegToRad).trimmed_utility);
      }
      const double loss = std::max(0.0, brute - found.evaluation.trimmed_utility);
      worst_loss = std::max(worst_loss, loss);
      total_loss += loss;
      ++total;
    }
  }
  EXPECT_LE(worst_loss, 0.01);
  EXPECT_LE(total_loss / total, 5e-4);
}

}  // namespace
}  // namespace foresight
