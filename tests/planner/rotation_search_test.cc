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
      RotationObjective objective = [&](double rho) { return evaluator.Evaluate(kick, rho); };
      const RotationChoice found = BestRotation(objective, s.evaluation.rotation_search);
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
