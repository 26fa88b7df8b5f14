// Coverage of random 2-vs-2 attacks by the shipped case base (cbr/coverage.h). The figures,
// 2000 situations a region with seed 13, are in models/cases/README.md; this test keeps their
// floor, so a change of the cases or of retrieval that loses coverage fails here.
#include "cbr/coverage.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "tests/support/temp_files.h"

namespace foresight {
namespace {

// The shipped retrieval parameters with the case base's kicks, as the team retrieves.
RetrievalParams ShippedParams(const LoadedCaseBase& base) {
  RetrievalParams params =
      LoadRetrievalParams(testing::ModelsDir() / "cbr" / "retrieval.json", base.rules.field);
  UseKickModelReach(base.rules.kicks, &params);
  return params;
}

TEST(CoverageTest, TheShippedCaseBaseRetrievesForMostAttacks) {
  const LoadedCaseBase base =
      LoadCaseBase(DefaultCaseBasePath(testing::ModelsDir()), testing::ModelsDir());
  const RetrievalParams params = ShippedParams(base);
  const AttackCoverage cyan = MeasureAttackCoverage(base, DefendingGoal::kCyan, params, 2000, 13);
  ASSERT_EQ(cyan.regions.size(), AttackRegions().size());
  EXPECT_EQ(cyan.regions[0].name, "back");
  // Measured: in scope 0.989, retrieved 0.901, cooperative 0.460.
  EXPECT_GE(cyan.in_scope, 0.98);
  EXPECT_GE(cyan.retrieved, 0.89);
  EXPECT_GE(cyan.cooperative, 0.45);
  for (const RegionCoverage& r : cyan.regions) {
    SCOPED_TRACE(r.name);
    EXPECT_EQ(r.samples, 2000);
    EXPECT_LE(r.retrieved, r.in_scope);
    EXPECT_LE(r.cooperative, r.retrieved);
    EXPECT_GE(r.retrieved, 0.81 * r.samples);  // the weakest region, front, retrieves 0.823
    EXPECT_LE(r.retrieved + r.too_far + r.blocked, r.in_scope);
    std::printf("%-10s in scope %.3f retrieved %.3f pass %.3f too far %.3f blocked %.3f\n",
                r.name.c_str(), 1.0 * r.in_scope / r.samples, 1.0 * r.retrieved / r.samples,
                1.0 * r.cooperative / r.samples, 1.0 * r.too_far / r.samples,
                1.0 * r.blocked / r.samples);
  }
  std::printf("all        in scope %.4f retrieved %.4f pass %.4f\n", cyan.in_scope, cyan.retrieved,
              cyan.cooperative);
  // The same situations mirrored for the other goal retrieve the mirrored cases.
  const AttackCoverage yellow =
      MeasureAttackCoverage(base, DefendingGoal::kYellow, params, 2000, 13);
  EXPECT_DOUBLE_EQ(yellow.in_scope, cyan.in_scope);
  EXPECT_NEAR(yellow.retrieved, cyan.retrieved, 1e-3);
  EXPECT_NEAR(yellow.cooperative, cyan.cooperative, 1e-3);
}

TEST(CoverageTest, WithoutOpponentsEveryAttackInScopeRetrievesSomething) {
  // Without a defender and a goalie (home regions off the field) nothing blocks a path, and the
  // cost test never fails here (teammates within 1.5 m): retrieved == in scope.
  const LoadedCaseBase base =
      LoadCaseBase(DefaultCaseBasePath(testing::ModelsDir()), testing::ModelsDir());
  AttackSpec spec;
  spec.defender = {-20.0, -20.0, 0.0, 0.0};
  spec.goalie = {-20.0, -20.0, 0.0, 0.0};
  const AttackCoverage cov =
      MeasureAttackCoverage(base, DefendingGoal::kCyan, RetrievalParams{}, 300, 14, spec);
  for (const RegionCoverage& r : cov.regions) {
    EXPECT_EQ(r.retrieved, r.in_scope) << r.name;
    EXPECT_EQ(r.blocked, 0) << r.name;
  }
}

}  // namespace
}  // namespace foresight
