#include "physics/bullet_world.h"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <LinearMath/btAlignedAllocator.h>

#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <mutex>
#include <new>

namespace foresight {

namespace {

// Bullet's allocator returns null when malloc fails, and Bullet then writes through the null
// pointer: under an address-space limit (`ulimit -v`) a run ended in SIGSEGV. Installed before
// main (this file is in every program that uses Bullet), this one throws std::bad_alloc
// instead, which ParallelFor and the commands handle (common/parallel_for.h). Only the plain
// allocation is replaced: Bullet's aligned allocator goes through it, and memory from before
// the switch is malloc's either way.
void* AllocateOrThrow(std::size_t size) {
  if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;  // malloc(0) may be null
  throw std::bad_alloc();
}

void Free(void* memory) {
  std::free(memory);
}

[[maybe_unused]] const bool kThrowingAllocator = [] {
  btAlignedAllocSetCustom(AllocateOrThrow, Free);
  return true;
}();

}  // namespace

Contact ContactOf(BodyTag tag) {
  switch (tag) {
    case BodyTag::kPost:
      return Contact::kPost;
    case BodyTag::kNet:
      return Contact::kNet;
    case BodyTag::kObstacle:
      return Contact::kObstacle;
    case BodyTag::kKicker:
      return Contact::kRobot;
    default:
      return Contact::kNone;
  }
}

BodyTag TagOf(const btCollisionObject& object) {
  return static_cast<BodyTag>(object.getUserIndex());
}

void MakeContactsNonSpeculative(btCollisionObject& object) {
  object.setContactProcessingThreshold(0.0);
}

namespace {

// A new or refreshed contact of a striking body (see MakeStriking): with the ball, no Baumgarte
// term; with anything else, the robot's own friction and restitution.
bool OnStrikingContact(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                       const btCollisionObjectWrapper* b, int, int) {
  const btCollisionObject& object_a = *a->getCollisionObject();
  const btCollisionObject& object_b = *b->getCollisionObject();
  if (TagOf(object_a) == BodyTag::kBall || TagOf(object_b) == BodyTag::kBall) {
    point.m_contactPointFlags |= BT_CONTACT_FLAG_HAS_CONTACT_ERP;
    point.m_contactERP = 0.0;
    return true;
  }
  const btCollisionObject& robot = TagOf(object_a) == BodyTag::kKicker ? object_a : object_b;
  if (const auto* material = static_cast<const Material*>(robot.getUserPointer())) {
    point.m_combinedFriction = static_cast<btScalar>(material->friction);
    point.m_combinedRestitution = static_cast<btScalar>(material->restitution);
  }
  return true;
}

// Bullet gives a pair of bodies the smaller of their contact processing thresholds; this one
// makes every pair of the ball with anything but the carpet non-speculative (see
// MakeContactsNonSpeculative), whatever the other body's own threshold.
class ContactDispatcher final : public btCollisionDispatcher {
 public:
  using btCollisionDispatcher::btCollisionDispatcher;
  btPersistentManifold* getNewManifold(const btCollisionObject* a,
                                       const btCollisionObject* b) override {
    btPersistentManifold* manifold = btCollisionDispatcher::getNewManifold(a, b);
    const BodyTag tag_a = TagOf(*a), tag_b = TagOf(*b);
    const bool ball = tag_a == BodyTag::kBall || tag_b == BodyTag::kBall;
    const bool carpet = tag_a == BodyTag::kCarpet || tag_b == BodyTag::kCarpet;
    if (ball && !carpet) manifold->setContactProcessingThreshold(0.0);
    return manifold;
  }
};

}  // namespace

namespace {

// The deepest overlap among the contacts a pair test reports (negative distances).
struct DeepestOverlap final : btCollisionWorld::ContactResultCallback {
  double depth_m = 0.0;
  btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper*, int, int,
                           const btCollisionObjectWrapper*, int, int) override {
    depth_m = std::max(depth_m, -static_cast<double>(point.getDistance()));
    return 0;
  }
};

bool IsStaticObstruction(BodyTag tag) {
  return tag == BodyTag::kPost || tag == BodyTag::kNet || tag == BodyTag::kObstacle;
}

}  // namespace

double KickerStaticOverlapM(btCollisionWorld& world) {
  std::vector<btCollisionObject*> kicker, statics;
  btCollisionObjectArray& objects = world.getCollisionObjectArray();
  for (int i = 0; i < objects.size(); ++i) {
    btCollisionObject* object = objects[i];
    const btBroadphaseProxy* proxy = object->getBroadphaseHandle();
    if (TagOf(*object) == BodyTag::kKicker && proxy != nullptr &&
        (proxy->m_collisionFilterMask & kGroupStatic) != 0) {
      kicker.push_back(object);
    } else if (IsStaticObstruction(TagOf(*object))) {
      statics.push_back(object);
    }
  }
  // Pair tests, not the world's collision pass: they leave the world's contact caches as they
  // were, so a trial whose robot stands clear steps exactly as without the test.
  DeepestOverlap deepest;
  for (btCollisionObject* link : kicker) {
    for (btCollisionObject* body : statics) world.contactPairTest(link, body, deepest);
  }
  return deepest.depth_m;
}

void MakeStriking(btCollisionObject& object, const Material* robot_contact) {
  // Bullet has one process-wide hook; it is set once, to a function without state, before any
  // world steps (worlds run in parallel threads). Per-world values reach it through the
  // robot's user pointer.
  static std::once_flag once;
  std::call_once(once, [] { gContactAddedCallback = OnStrikingContact; });
  object.setCollisionFlags(object.getCollisionFlags() |
                           btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
  object.setUserPointer(const_cast<Material*>(robot_contact));
}

namespace {

std::unique_ptr<btCollisionConfiguration> MakeConfig() {
  // Small pools: a trial's world holds a handful of contacts, and allocating Bullet's default
  // pools (thousands of manifolds) would cost more than a whole free roll.
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = 256;
  info.m_defaultMaxCollisionAlgorithmPoolSize = 256;
  return std::make_unique<btDefaultCollisionConfiguration>(info);
}

}  // namespace

BulletWorld::BulletWorld(Kind kind, const SolverSettings& solver)
    : config_(MakeConfig()),
      dispatcher_(std::make_unique<ContactDispatcher>(config_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()) {
  if (kind == Kind::kMultiBody) {
    auto solver = std::make_unique<btMultiBodyConstraintSolver>();
    auto world = std::make_unique<btMultiBodyDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                            solver.get(), config_.get());
    multibody_world_ = world.get();
    solver_ = std::move(solver);
    world_ = std::move(world);
  } else {
    solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
    world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                       solver_.get(), config_.get());
  }
  world_->setGravity(btVector3(0, 0, -9.81));
  btContactSolverInfo& info = world_->getSolverInfo();
  info.m_numIterations = solver.iterations;
  info.m_restitutionVelocityThreshold = static_cast<btScalar>(solver.restitution_threshold_mps);
  // Always split: an overlap is undone by moving the bodies apart, never by adding speed. By
  // default only overlaps deeper than 4 cm are split and the rest get Baumgarte's
  // 0.2 * overlap / dt on top of the bounce, a rebound that grows with the step's phase.
  info.m_splitImpulse = 1;
  info.m_splitImpulsePenetrationThreshold = 0.0;
}

BulletWorld::~BulletWorld() {
  // Remove everything before the objects die; Bullet only holds raw pointers.
  for (auto& constraint : constraints_)
    multibody_world_->removeMultiBodyConstraint(constraint.get());
  for (auto& body : multibodies_) multibody_world_->removeMultiBody(body.get());
  for (auto& object : objects_) {
    if (auto* body = btRigidBody::upcast(object.get())) {
      world_->removeRigidBody(body);
    } else {
      world_->removeCollisionObject(object.get());
    }
  }
}

btRigidBody* BulletWorld::AddStatic(btCollisionShape* shape, const btTransform& pose_F, BodyTag tag,
                                    Material material) {
  btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, shape);
  info.m_startWorldTransform = pose_F;
  info.m_restitution = material.restitution;
  info.m_friction = material.friction;
  auto body = std::make_unique<btRigidBody>(info);
  body->setUserIndex(static_cast<int>(tag));
  if (tag != BodyTag::kCarpet) MakeContactsNonSpeculative(*body);
  btRigidBody* raw = body.get();
  objects_.push_back(std::move(body));
  world_->addRigidBody(raw, kGroupStatic, kGroupBall | kGroupKicker);
  return raw;
}

btRigidBody* BulletWorld::AddDynamic(btCollisionShape* shape, double mass_kg,
                                     const btVector3& inertia_kgm2, const btTransform& pose_F,
                                     BodyTag tag, Material material, int group, int mask) {
  btRigidBody::btRigidBodyConstructionInfo info(mass_kg, nullptr, shape, inertia_kgm2);
  info.m_startWorldTransform = pose_F;
  info.m_restitution = material.restitution;
  info.m_friction = material.friction;
  auto body = std::make_unique<btRigidBody>(info);
  body->setUserIndex(static_cast<int>(tag));
  body->setActivationState(DISABLE_DEACTIVATION);
  btRigidBody* raw = body.get();
  objects_.push_back(std::move(body));
  world_->addRigidBody(raw, group, mask);
  return raw;
}

btMultiBody* BulletWorld::AddMultiBody(std::unique_ptr<btMultiBody> body) {
  assert(multibody_world_ != nullptr);
  btMultiBody* raw = body.get();
  multibodies_.push_back(std::move(body));
  multibody_world_->addMultiBody(raw, kGroupKicker, kGroupBall);
  return raw;
}

void BulletWorld::AddCollider(std::unique_ptr<btCollisionObject> collider, int group, int mask) {
  btCollisionObject* raw = collider.get();
  objects_.push_back(std::move(collider));
  world_->addCollisionObject(raw, group, mask);
}

void BulletWorld::AddConstraint(std::unique_ptr<btMultiBodyConstraint> constraint) {
  assert(multibody_world_ != nullptr);
  multibody_world_->addMultiBodyConstraint(constraint.get());
  constraints_.push_back(std::move(constraint));
}

}  // namespace foresight
