// Ball contacts realise their materials: the rebound off a post or a net is e * v at any speed
// and wherever in the time step the contact falls, and the ball never gets deeper into what it
// hits than the step allows (no tunnelling).
#include "physics/impact_probe.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/support/physics_test_scenes.h"

namespace foresight {
namespace {

constexpr int kPhases = 20;
constexpr double kReboundToleranceRel = 0.05;  // the bound: 5 % of e * v ...
constexpr double kReboundFloorMps = 0.005;     // ... or 5 mm/s

class ReboundTest : public ::testing::TestWithParam<ImpactTarget> {
 protected:
  std::unique_ptr<testing::PhysicsFixtureData> data_ = testing::LoadPhysicsFixture("spl", true);
  PhysicsScene scene_ = testing::SceneOf(*data_);

  double GapAt(double speed_mps, double phase) const { return GapAtPhase(scene_, speed_mps, phase); }
};

TEST_P(ReboundTest, ReboundIsRestitutionTimesApproachAtEveryPhase) {
  const double e = TargetRestitution(scene_, GetParam());
  for (double v : {0.3, 1.0, 2.0, 5.0, 10.0}) {
    for (int k = 0; k < kPhases; ++k) {
      const ImpactResult r = FireAt(scene_, GetParam(), v, GapAt(v, k / double(kPhases)));
      ASSERT_TRUE(r.touched) << v << " m/s, phase " << k;
      const double expected = e * r.approach_mps;
      EXPECT_NEAR(r.rebound_mps, expected, std::max(kReboundFloorMps, kReboundToleranceRel * expected))
          << v << " m/s, phase " << k << ", approach " << r.approach_mps;
      EXPECT_GT(r.approach_mps, 0.9 * v - 0.05) << v << " m/s, phase " << k;
    }
  }
}

TEST_P(ReboundTest, NoTunnellingUpTo12MpsAtEveryPhase) {
  const double max_overlap = data_->params.steps.max_overlap_m;
  for (double v : {6.0, 8.0, 10.0, 12.0}) {
    for (int k = 0; k < kPhases; ++k) {
      const ImpactResult r = FireAt(scene_, GetParam(), v, GapAt(v, k / double(kPhases)));
      ASSERT_TRUE(r.touched) << v << " m/s, phase " << k;
      // One step moves the ball at most max_overlap (plus what the solver's push-out leaves).
      EXPECT_LE(r.penetration_m, max_overlap + 1e-3) << v << " m/s, phase " << k;
      EXPECT_GT(r.rebound_mps, 0.0) << v << " m/s, phase " << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, ReboundTest,
                         ::testing::Values(ImpactTarget::kPost, ImpactTarget::kBackNet,
                                           ImpactTarget::kSideNet),
                         [](const auto& info) { return std::string(ImpactTargetName(info.param)); });

}  // namespace
}  // namespace foresight
