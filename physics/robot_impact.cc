#include "physics/robot_impact.h"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "physics/ball_placement.h"
#include "physics/bullet_convert.h"
#include "physics/bullet_world.h"
#include "physics/carpet.h"
#include "physics/phases.h"
#include "physics/physics_scene.h"
#include "physics/robot_kinematics.h"

namespace foresight {

namespace {

// The robot's contact with the ball that carries an impulse in this step, if any: its normal
// from the robot to the ball.
bool ImpactNormal(btDispatcher& dispatcher, const btCollisionObject& ball, Eigen::Vector3d& n_F) {
  for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
    const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
    const bool ball_first = m->getBody0() == &ball;
    if (!ball_first && m->getBody1() != &ball) continue;
    const btCollisionObject& other = ball_first ? *m->getBody1() : *m->getBody0();
    if (TagOf(other) != BodyTag::kObstacle) continue;
    for (int k = 0; k < m->getNumContacts(); ++k) {
      const btManifoldPoint& point = m->getContactPoint(k);
      if (point.getAppliedImpulse() <= 0.0) continue;
      // Bullet's normal points from body 1 to body 0.
      n_F = ToEigen(point.m_normalWorldOnB) * (ball_first ? 1.0 : -1.0);
      return true;
    }
  }
  return false;
}

}  // namespace

double RobotImpactResult::NormalRestitution() const {
  const double into = -before.v_F.dot(n_F);
  return into > 0.0 ? after.v_F.dot(n_F) / into : 0.0;
}

double RobotImpactResult::ReboundRatio() const {
  const double approach = -before.v_F.x();
  return approach > 0.0 ? after.v_F.x() / approach : 0.0;
}

RobotImpactResult RollIntoRobot(const FieldSpec& field, const PhysicsParams& params,
                                const Robot& robot, const std::string& link, double speed_mps,
                                double gap_m) {
  const std::optional<int> index = robot.model.FindLink(link);
  if (!index) throw InputError("link: " + robot.spec.name + " has no link '" + link + "'");
  const std::vector<double> q = robot.StandingPositions();
  const double y = LinkPoses(robot.model, q)[*index].translation().y();
  // Where along y the ball first touches the robot: bisect between touching and 1 m clear.
  const double r = field.ball.radius_m;
  const StanceClearance clearance(robot, q, robot.spec.base_height_m, r);
  double inside = 0.0, clear = 1.0;
  if (clearance.DepthInsideM(Vec2(inside, y)) <= 0.0)
    throw InputError("link: a ball rolled at " + link + " passes the robot");
  while (clear - inside > 1e-6) {
    const double mid = 0.5 * (inside + clear);
    (clearance.DepthInsideM(Vec2(mid, y)) > 0.0 ? inside : clear) = mid;
  }
  const PhysicsScene scene = MakePhysicsScene(field, params, &robot, {Obstacle{Vec2(0, 0), 0.0}},
                                              Vec2(1.0, 0.0));  // facing +x, towards the ball
  const Carpet carpet(params.carpet, 1.0);
  BallMonitor monitor(scene.lines, Vec2(clear + gap_m, y), true);
  RobotImpactResult result;
  int impact_step = -1;
  int step = 0;
  const RollStepObserver observe = [&](btDispatcher& dispatcher, const btCollisionObject& ball) {
    if (impact_step < 0 && ImpactNormal(dispatcher, ball, result.n_F)) impact_step = step;
    ++step;
  };
  RunRollPhase(scene, carpet, RollingBall(Vec2(clear + gap_m, y), r, speed_mps, kPi), 0.0, monitor,
               observe);
  const std::vector<TracePoint>& trace = monitor.trace();
  result.touched = impact_step >= 0;
  if (!result.touched || impact_step == 0) return result;
  const auto state = [&](int i) { return BallState{trace[i].p_F, trace[i].v_F, trace[i].w_F}; };
  result.before = state(impact_step - 1);
  result.after = state(impact_step);
  for (std::size_t i = impact_step; i < trace.size(); ++i)
    result.max_height_m = std::max(result.max_height_m, trace[i].p_F.z() - r);
  return result;
}

RigidImpact PredictRigidImpact(const BallState& before, const Eigen::Vector3d& n_F, double radius_m,
                               double inertia_factor, double restitution, double friction) {
  const Eigen::Vector3d rho = -radius_m * n_F;  // centre to the contact point
  const Eigen::Vector3d u = before.v_F + before.w_F.cross(rho);
  const double u_n = u.dot(n_F);
  // Impulses per unit mass. A sphere's normal impulse does not turn it (rho is along n), so the
  // normal and tangential parts are independent.
  const double j_n = u_n < 0.0 ? -(1.0 + restitution) * u_n : 0.0;
  const Eigen::Vector3d u_t = u - u_n * n_F;
  const double slip = u_t.norm();
  const double j_stick = slip / (1.0 + 1.0 / inertia_factor);
  const double j_t = std::min(j_stick, friction * j_n);
  const Eigen::Vector3d t = slip > 0.0 ? Eigen::Vector3d(-u_t / slip) : Eigen::Vector3d::Zero();
  RigidImpact out;
  out.v_F = before.v_F + j_n * n_F + j_t * t;
  out.w_F = before.w_F + rho.cross(j_t * t) / (inertia_factor * radius_m * radius_m);
  return out;
}

}  // namespace foresight
