// One Bullet world and everything in it, owned together and torn down in the right order.
//
// Bullet objects point at each other (world -> bodies -> shapes -> ...), so this class owns
// them all and destroys the world first. Every collision object carries a BodyTag in its user
// index, from which contacts are classified. Worlds are never shared between threads; one world
// per trial keeps trials independent (and so deterministic whatever the thread count).
#pragma once

#include <btBulletDynamicsCommon.h>

#include <memory>
#include <utility>
#include <vector>

#include "models/outcome.h"

class btMultiBodyDynamicsWorld;
class btMultiBody;
class btMultiBodyConstraint;

namespace foresight {

enum class BodyTag : int { kUntagged = 0, kCarpet, kBall, kPost, kNet, kObstacle, kKicker };

// The contact kind the ball reports when it touches a body with this tag.
Contact ContactOf(BodyTag tag);
BodyTag TagOf(const btCollisionObject& object);

// What the ball bounces off (posts, nets, robots: everything but the carpet) gets no speculative
// contacts (for statics through this function; for the ball's pairs with the kicking robot
// through the world's dispatcher, ContactDispatcher in bullet_world.cc, so that the robot's
// own soles stay speculative on the carpet). Bullet otherwise reports a contact while a gap remains
// and aims at a separation speed e*v - gap/dt, so the ball arrives too slowly to bounce
// (restitution lost, or random with where in the step the contact falls). Such contacts are solved
// once the bodies overlap; the roll's time steps keep the overlap small (physics_scene.h,
// RollTimeStep). A pair's threshold is the smaller of its bodies', so the carpet keeps Bullet's
// default and the ball rests on it without falling in and out of contact every step.
void MakeContactsNonSpeculative(btCollisionObject& object);

// The kicking robot's links strike the ball. Bullet's multibody contacts have no split impulse:
// an overlap is pushed apart by Baumgarte's 0.2 * overlap / dt on top of the bounce, so the ball
// left the foot up to 20 % faster or slower depending on where in the step the contact fell
// (a launch spread of about 0.04 m/s that no physical cause made). Their contacts with the
// ball get no positional correction at all: the overlap lasts the few milliseconds of the
// strike. Their other contacts (a robot standing on its own feet) keep Bullet's Baumgarte
// correction, and with the carpet speculative contacts, which hold a sole resting on it (the
// other statics, posts, nets and obstacles, are made non-speculative for the ball, AddStatic,
// and Bullet takes the pair's smaller threshold, so the robot's contacts with them are too)
// (without them a standing NAO crept 16 mm and tilted 2.8 deg in 2 s), and get the friction and
// restitution of `robot_contact`, which must outlive the world's steps (models/physics_params.h,
// RobotContactParams).
struct Material;
void MakeStriking(btCollisionObject& object, const Material* robot_contact = nullptr);

// Collision groups: statics touch the ball and the robot; a fixed-base kicking robot touches
// only the ball (carpet contacts would only fight the motors), a floating one everything.
enum CollisionGroup : int {
  kGroupStatic = 1 << 0,
  kGroupBall = 1 << 1,
  kGroupKicker = 1 << 2,
};

// How deep the kicking robot, as its colliders stand now, reaches into a post, net or obstacle
// robot (metres; 0 when clear). Only colliders that collide with statics count (a floating
// robot's; a fixed-base robot passes through them). A robot created overlapping a static body is
// thrown out of it by the contact solver in its first step (several N s), which no real robot
// standing there could survive or would be in: it could not have got there.
double KickerStaticOverlapM(btCollisionWorld& world);

struct Material {
  double restitution = 0.0;
  double friction = 0.0;
};
// Bullet multiplies the two bodies' coefficients; the ball's are 1, so the other body's value
// is the pair's (models/physics_params.h).
inline constexpr Material kBallMaterial{1.0, 1.0};

// The contact solver's settings for the ball's contacts.
struct SolverSettings {
  int iterations = 0;
  double restitution_threshold_mps = 0.0;
};

class BulletWorld {
 public:
  enum class Kind { kRigid, kMultiBody };
  BulletWorld(Kind kind, const SolverSettings& solver);
  ~BulletWorld();
  BulletWorld(const BulletWorld&) = delete;
  BulletWorld& operator=(const BulletWorld&) = delete;

  btDiscreteDynamicsWorld& world() { return *world_; }
  const btDiscreteDynamicsWorld& world() const { return *world_; }
  btMultiBodyDynamicsWorld* multibody_world() { return multibody_world_; }

  // Takes ownership of a shape and returns it for use in bodies of this world.
  template <class Shape>
  Shape* Own(std::unique_ptr<Shape> shape) {
    Shape* raw = shape.get();
    shapes_.push_back(std::move(shape));
    return raw;
  }
  // A static body (posts, nets, carpet, obstacle robots).
  btRigidBody* AddStatic(btCollisionShape* shape, const btTransform& pose_F, BodyTag tag,
                         Material material);
  // A dynamic rigid body (the ball) with the principal moments of inertia inertia_kgm2.
  btRigidBody* AddDynamic(btCollisionShape* shape, double mass_kg, const btVector3& inertia_kgm2,
                          const btTransform& pose_F, BodyTag tag, Material material, int group,
                          int mask);
  // Takes ownership of a multibody, its colliders and constraints (multibody worlds only).
  btMultiBody* AddMultiBody(std::unique_ptr<btMultiBody> body);
  void AddCollider(std::unique_ptr<btCollisionObject> collider, int group, int mask);
  void AddConstraint(std::unique_ptr<btMultiBodyConstraint> constraint);

 private:
  // Declaration order is destruction order reversed: the world goes first.
  std::unique_ptr<btCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;  // a ContactDispatcher
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btConstraintSolver> solver_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btCollisionObject>> objects_;
  std::vector<std::unique_ptr<btMultiBody>> multibodies_;
  std::vector<std::unique_ptr<btMultiBodyConstraint>> constraints_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  btMultiBodyDynamicsWorld* multibody_world_ = nullptr;
};

}  // namespace foresight
