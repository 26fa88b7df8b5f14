// The goal's bounding circle tested by squared distance (planner/coarse_world.h SquaredBound):
// the same answer as comparing the correctly rounded square root with the radius.
#include "planner/coarse_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/random.h"
#include "planner/coarse_planner.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

TEST(CoarseWorldTest, SquaredBoundGivesTheRootsComparison) {
  RandomStream rng(StreamKey(43, 0));
  const Situation s = testing::MakeSituation({});
  const CoarseWorld world = CoarseWorld::Build(MakeScene(s));
  std::vector<double> radii = {world.goals[0].bound_radius_m, world.goals[1].bound_radius_m, 0.0,
                               1e-300, 1.0, 3.0};
  for (int i = 0; i < 200; ++i) radii.push_back(10.0 * rng.NextUniform());
  int near_edge = 0;
  for (double r : radii) {
    const double bound = SquaredBound(r);
    EXPECT_LE(std::sqrt(bound), r) << r;
    EXPECT_GT(std::sqrt(std::nextafter(bound, INFINITY)), r) << r;
    // Every double within 64 steps of r * r, and random ones around it.
    double d = r * r;
    for (int k = 0; k < 64; ++k) d = std::nextafter(d, 0.0);
    for (int k = 0; k < 128; ++k, d = std::nextafter(d, INFINITY)) {
      ASSERT_EQ(std::sqrt(d) > r, d > bound) << r << " " << d;
      near_edge += std::sqrt(d) == r;
    }
    for (int k = 0; k < 200; ++k) {
      const double x = 2.0 * r * r * rng.NextUniform();
      ASSERT_EQ(std::sqrt(x) > r, x > bound) << r << " " << x;
    }
  }
  EXPECT_GT(near_edge, 100);  // the steps do reach distances whose root rounds to the radius
  EXPECT_EQ(world.goals[0].bound_distance_sq_max, SquaredBound(world.goals[0].bound_radius_m));
}

}  // namespace
}  // namespace foresight
