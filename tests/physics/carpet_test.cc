// The carpet's deceleration: exactly a when uniform, a per-trial factor on top, and a fixed
// patch layout that varies between patches but not within one.
#include "physics/carpet.h"

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "physics/bullet_world.h"
#include "tests/support/physics_test_scenes.h"

namespace foresight {
namespace {

CarpetParams Shipped() {
  return testing::LoadPhysicsFixture("spl", false)->params.carpet;
}

// The carpet's bounding box ends at its surface, so a body high above it is not paired with it
// (no contact test per step); a body that comes down is paired in time and lands as on the
// unbounded plane: a box dropped from 0.5 m rests on it at its half height, and a ball thrown
// down at 6 m/s in 16 ms steps (5 cm more than its radius per step) bounces instead of tunnelling.
TEST(CarpetTest, BodiesHighAboveAreNotPairedAndLandWhenTheyComeDown) {
  const MaterialParams materials = testing::LoadPhysicsFixture("spl", false)->params.materials;
  struct Drop {
    double half_m, z0_m, vz0_mps, dt_s;
  };
  for (const Drop drop : {Drop{0.03, 0.5, 0.0, 0.002}, Drop{0.05, 0.3, -6.0, 0.016}}) {
    BulletWorld world(BulletWorld::Kind::kRigid, {10, 0.02});
    AddCarpetPlane(world, materials);
    btCollisionShape* shape =
        drop.vz0_mps == 0.0
            ? static_cast<btCollisionShape*>(
                  world.Own(std::make_unique<btBoxShape>(btVector3(1, 1, 1) * drop.half_m)))
            : world.Own(std::make_unique<btSphereShape>(drop.half_m));
    btVector3 inertia;
    shape->calculateLocalInertia(0.1, inertia);
    btRigidBody* body =
        world.AddDynamic(shape, 0.1, inertia, btTransform(btQuaternion::getIdentity(),
                                                          btVector3(0, 0, drop.z0_m)),
                         BodyTag::kBall, kBallMaterial, kGroupBall, kGroupStatic);
    body->setLinearVelocity(btVector3(0, 0, drop.vz0_mps));
    world.world().performDiscreteCollisionDetection();
    EXPECT_EQ(world.world().getPairCache()->getNumOverlappingPairs(), 0);
    for (int step = 0; step < static_cast<int>(2.0 / drop.dt_s); ++step) {
      world.world().stepSimulation(drop.dt_s, 0, drop.dt_s);
    }
    EXPECT_GT(body->getCenterOfMassPosition().z(), 0.0) << "fell through the carpet";
    if (drop.vz0_mps == 0.0) {
      EXPECT_NEAR(body->getCenterOfMassPosition().z(), drop.half_m, 0.002);
      EXPECT_EQ(world.world().getPairCache()->getNumOverlappingPairs(), 1);
    }
  }
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
