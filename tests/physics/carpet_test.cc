// The carpet's deceleration: exactly a when uniform, a per-trial factor on top, and a fixed
// patch layout that varies between patches but not within one.
#include "physics/carpet.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/physics_test_scenes.h"

namespace foresight {
namespace {

CarpetParams Shipped() {
  return testing::LoadPhysicsFixture("spl", false)->params.carpet;
}

TEST(CarpetTest, UniformCarpetDeceleratesAtItsA) {
  CarpetParams params = Shipped();
  params.patch_sigma_rel = 0.0;
  const Carpet carpet(params, 1.0);
  EXPECT_DOUBLE_EQ(carpet.DecelerationAt(Vec2(1.3, -2.2)), params.rolling_deceleration_mps2);
  EXPECT_DOUBLE_EQ(Carpet(params, 1.1).DecelerationAt(Vec2(0, 0)),
                   1.1 * params.rolling_deceleration_mps2);
}

TEST(CarpetTest, PatchesVaryBetweenPatchesNotWithinOne) {
  const CarpetParams params = Shipped();
  ASSERT_GT(params.patch_sigma_rel, 0.0);
  const Carpet carpet(params, 1.0);
  const double size = params.patch_size_m;
  // Two points of one patch agree; the layout does not depend on the Carpet object.
  EXPECT_EQ(carpet.DecelerationAt(Vec2(0.1 * size, 0.2 * size)),
            carpet.DecelerationAt(Vec2(0.9 * size, 0.7 * size)));
  EXPECT_EQ(carpet.DecelerationAt(Vec2(-2.5, 1.5)),
            Carpet(params, 1.0).DecelerationAt(Vec2(-2.5, 1.5)));
  // Over the SPL carpet the factors spread by about patch_sigma_rel around 1.
  double sum = 0.0, sum_sq = 0.0;
  int n = 0;
  for (int ix = -5; ix < 5; ++ix) {
    for (int iy = -4; iy < 4; ++iy) {
      const double f = carpet.DecelerationAt(Vec2((ix + 0.5) * size, (iy + 0.5) * size)) /
                       params.rolling_deceleration_mps2;
      sum += f;
      sum_sq += f * f;
      ++n;
    }
  }
  const double mean = sum / n;
  const double sd = std::sqrt(sum_sq / n - mean * mean);
  EXPECT_NEAR(mean, 1.0, 3.0 * params.patch_sigma_rel / std::sqrt(n));
  EXPECT_GT(sd, 0.5 * params.patch_sigma_rel);
  EXPECT_LT(sd, 1.5 * params.patch_sigma_rel);
}

}  // namespace
}  // namespace foresight
