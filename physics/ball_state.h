// The ball's state in F and what a trial watches of it: contacts, the category of its path,
// and optionally its trajectory.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "models/field_lines.h"
#include "models/outcome.h"

class btRigidBody;
class btDispatcher;
class btCollisionObject;

namespace foresight {

struct BallState {
  Eigen::Vector3d p_F = Eigen::Vector3d::Zero();  // centre, m
  Eigen::Vector3d v_F = Eigen::Vector3d::Zero();  // m/s
  Eigen::Vector3d w_F = Eigen::Vector3d::Zero();  // rad/s

  Vec2 Planar() const { return p_F.head<2>(); }
  double PlanarSpeed() const { return v_F.head<2>().norm(); }
  // Speed of the ball's lowest point over the carpet (0 when it rolls without sliding).
  double SlipSpeed(double radius_m) const;
};

// A ball rolling without sliding at speed_mps along heading_rad from p_F (centre at its radius).
BallState RollingBall(const Vec2& p_F, double radius_m, double speed_mps, double heading_rad);

BallState ReadBall(const btRigidBody& ball);
void WriteBall(btRigidBody& ball, const BallState& state);

struct TracePoint {
  double t_s = 0.0;
  Eigen::Vector3d p_F = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_F = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_F = Eigen::Vector3d::Zero();
  bool kicker_contact = false;  // the kicking robot touched the ball in this step
};

// What the ball touched in the last step.
struct StepContacts {
  bool kicker = false;             // the kicking robot
  Contact other = Contact::kNone;  // a post, net or obstacle
};
StepContacts ContactsOf(btDispatcher& dispatcher, const btCollisionObject& ball);

// Follows the ball step by step: the first line its path crosses decides the category (as in
// the coarse model, and a ball crossing a goal line over the crossbar is out), the first post,
// net or obstacle it touches is the first contact.
class BallMonitor {
 public:
  BallMonitor(const FieldLines& lines, const Vec2& p_F_start, bool record_trace);

  void Observe(double t_s, const BallState& state, const StepContacts& contacts);
  Category category() const { return category_; }
  Contact first_contact() const { return first_contact_; }
  std::vector<TracePoint>& trace() { return trace_; }

 private:
  const FieldLines& lines_;
  Vec2 last_p_F_;
  Category category_;
  Contact first_contact_ = Contact::kNone;
  bool record_trace_;
  std::vector<TracePoint> trace_;
};

}  // namespace foresight
