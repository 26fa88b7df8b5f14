#include "physics/carpet.h"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "common/random.h"
#include "physics/bullet_world.h"

namespace foresight {

namespace {

constexpr std::uint64_t kPatchDomain = 0x70a7c4;

// The plane z = 0 whose bounding box ends at its surface instead of reaching BT_LARGE_FLOAT
// upwards. Bullet pairs two objects for contact tests when their boxes overlap, and every box of
// a moving object is grown by gContactBreakingThreshold (2 cm) and its margin, while a contact
// point is only made within a link's breaking threshold (at most 2 cm): a box that stays clear of
// z <= 0 cannot touch the carpet. So the links of a standing robot above its feet are not tested
// against the carpet at every step (they were, with the plane's unbounded box), and any link that
// comes down to within 2 cm is paired and tested exactly as before.
class CarpetPlaneShape : public btStaticPlaneShape {
 public:
  CarpetPlaneShape() : btStaticPlaneShape(btVector3(0, 0, 1), 0.0) {}
  void getAabb(const btTransform& t, btVector3& aabb_min, btVector3& aabb_max) const override {
    btStaticPlaneShape::getAabb(t, aabb_min, aabb_max);
    aabb_max.setZ(0.0);  // the plane is z = 0 in the world: the carpet is never moved
  }
};

}  // namespace

void AddCarpetPlane(BulletWorld& world, const MaterialParams& materials) {
  auto* plane = world.Own(std::make_unique<CarpetPlaneShape>());
  world.AddStatic(plane, btTransform::getIdentity(), BodyTag::kCarpet,
                  {materials.restitution.carpet, materials.friction.carpet});
}

Carpet::Carpet(const CarpetParams& params, double trial_factor)
    : params_(params), trial_factor_(trial_factor) {}

double Carpet::DecelerationAt(const Vec2& p_F) const {
  double factor = trial_factor_;
  if (params_.patch_sigma_rel > 0.0) {
    const auto ix = static_cast<std::int64_t>(std::floor(p_F.x() / params_.patch_size_m));
    const auto iy = static_cast<std::int64_t>(std::floor(p_F.y() / params_.patch_size_m));
    const std::uint64_t cell =
        (static_cast<std::uint64_t>(ix) << 32) ^ static_cast<std::uint64_t>(iy & 0xffffffff);
    RandomStream stream(StreamKey(params_.patch_seed, cell, kPatchDomain));
    factor *= std::clamp(1.0 + params_.patch_sigma_rel * stream.NextNormal(), 0.5, 1.5);
  }
  return params_.rolling_deceleration_mps2 * factor;
}

void Carpet::ApplyRollingResistance(btRigidBody& ball, double radius_m, double dt_s) const {
  const btVector3& p = ball.getCenterOfMassPosition();
  if (!TouchesCarpet(p.z(), radius_m)) return;
  btVector3 v = ball.getLinearVelocity();
  const btVector3 slip = v + ball.getAngularVelocity().cross(btVector3(0, 0, -radius_m));
  v.setZ(0.0);
  const double speed = v.length();
  if (speed <= 0.0 || IsSliding(btVector3(slip.x(), slip.y(), 0).length(), speed)) return;
  const double mass = 1.0 / ball.getInvMass();
  const double k = 1.0 / (ball.getInvInertiaDiagLocal().x() * mass * radius_m * radius_m);
  const double deceleration = std::min(DecelerationAt(Vec2(p.x(), p.y())), speed / dt_s);
  ball.applyCentralForce(v * (-(1.0 + k) * mass * deceleration / speed));
}

}  // namespace foresight
