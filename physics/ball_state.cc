#include "physics/ball_state.h"

#include <btBulletDynamicsCommon.h>

#include <cmath>

#include "physics/bullet_convert.h"
#include "physics/bullet_world.h"

namespace foresight {

double BallState::SlipSpeed(double radius_m) const {
  const Eigen::Vector3d contact_velocity = v_F + w_F.cross(Eigen::Vector3d(0, 0, -radius_m));
  return contact_velocity.head<2>().norm();
}

BallState RollingBall(const Vec2& p_F, double radius_m, double speed_mps, double heading_rad) {
  const Eigen::Vector3d dir(std::cos(heading_rad), std::sin(heading_rad), 0.0);
  BallState state;
  state.p_F = Eigen::Vector3d(p_F.x(), p_F.y(), radius_m);
  state.v_F = speed_mps * dir;
  // Rolling: the contact point rests, v + w x (-r z) = 0, so w = (v / r) z x dir.
  state.w_F = (speed_mps / radius_m) * Eigen::Vector3d::UnitZ().cross(dir);
  return state;
}

BallState ReadBall(const btRigidBody& ball) {
  BallState state;
  state.p_F = ToEigen(ball.getCenterOfMassPosition());
  state.v_F = ToEigen(ball.getLinearVelocity());
  state.w_F = ToEigen(ball.getAngularVelocity());
  return state;
}

void WriteBall(btRigidBody& ball, const BallState& state) {
  btTransform pose = btTransform::getIdentity();
  pose.setOrigin(ToBt(state.p_F));
  ball.setWorldTransform(pose);
  ball.setCenterOfMassTransform(pose);
  ball.setLinearVelocity(ToBt(state.v_F));
  ball.setAngularVelocity(ToBt(state.w_F));
}

StepContacts ContactsOf(btDispatcher& dispatcher, const btCollisionObject& ball) {
  StepContacts contacts;
  const int manifolds = dispatcher.getNumManifolds();
  for (int i = 0; i < manifolds; ++i) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(i);
    const btCollisionObject* a = manifold->getBody0();
    const btCollisionObject* b = manifold->getBody1();
    if (a != &ball && b != &ball) continue;
    bool touching = false;
    for (int k = 0; k < manifold->getNumContacts() && !touching; ++k) {
      // A fast ball is often stopped by a speculative contact: the solver pushes it back while
      // the point is still a little apart, so an applied impulse counts as a touch too.
      const btManifoldPoint& point = manifold->getContactPoint(k);
      touching = point.getDistance() <= 1e-3 || point.getAppliedImpulse() > 0.0;
    }
    if (!touching) continue;
    const BodyTag tag = TagOf(a == &ball ? *b : *a);
    if (tag == BodyTag::kKicker) {
      contacts.kicker = true;
    } else if (contacts.other == Contact::kNone) {
      contacts.other = ContactOf(tag);
    }
  }
  return contacts;
}

BallMonitor::BallMonitor(const FieldLines& lines, const Vec2& p_F_start, bool record_trace)
    : lines_(lines),
      last_p_F_(p_F_start),
      category_(ClassifyPosition(lines, p_F_start)),
      record_trace_(record_trace) {}

void BallMonitor::Observe(double t_s, const BallState& state, const StepContacts& contacts) {
  const Contact contact = contacts.other;
  if (first_contact_ == Contact::kNone) first_contact_ = contact;
  const Vec2 p = state.Planar();
  if (category_ == Category::kInfield) {
    const Vec2 step = p - last_p_F_;
    const double length = step.norm();
    if (length > 0.0) category_ = ClassifyPath(lines_, last_p_F_, step / length, length);
    const bool goal = category_ == Category::kOppGoal || category_ == Category::kOwnGoal;
    if (goal && state.p_F.z() > lines_.goal_max_centre_z_m) category_ = Category::kOut;
  }
  last_p_F_ = p;
  if (record_trace_) trace_.push_back({t_s, state.p_F, state.v_F, state.w_F, contacts.kicker});
}

}  // namespace foresight
