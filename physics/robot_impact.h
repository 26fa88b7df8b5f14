// A ball rolled head-on at a standing robot's link (the NAO's foot, the AIBO's front paw), what
// the impact did in Bullet, and what rigid-body impact theory says it should do.
//
// The robot stands still in robot.json's standing pose as an obstacle robot (a static body of
// the pair ball_robot, physics_scene.h); the ball rolls without sliding along -x of F into the
// link, aimed at the link frame's y, from `gap_m` in front of where it first touches the robot.
// The roll is the roll phase's own (phases.h: its steps, carpet and contacts).
//
// Why a rolled ball does not come back at e * v (measured 0.04-0.06 of v off the NAO's
// foot, the ball hopping up at half its speed). Newton's restitution e acts along the contact
// normal n, Coulomb's friction mu in the tangent plane (models/physics_params.h). Two things
// take the horizontal rebound away from e * v, and neither is a solver artefact:
//  - The normal is not horizontal. The SPL ball's centre is 50 mm up and the NAO's foot is
//    45.19 mm tall, its toe rounded: the ball meets the toe's upper front, n about 15 deg above
//    the horizontal (the AIBO's paw about 5.5 deg). Frictionless, a ball meeting a toe tilted by
//    phi leaves at (1 + e) cos^2(phi) - 1 of v backwards and (1 + e) cos(phi) sin(phi) of v
//    upwards: 0.10 v back and 0.29 v up for the NAO.
//  - A rolling ball has topspin: where it meets the link its surface slides down at about v.
//    Friction stops that slip with an upward impulse, up to mu times the normal impulse; the
//    slip of a ball of inertia k m r^2 stops after a tangential impulse of m |u_t| / (1 + 1/k).
//    That impulse lifts the ball (the hop) and, on a tilted normal, pushes it back towards the
//    robot. Against a vertical goal post the same friction lifts the SPL ball 2/7 of its speed
//    (1.6 cm at 2 m/s), which the post checks do not look at.
// PredictRigidImpact is that theory for one instantaneous impact with a static body (the carpet
// under the ball ignored); Bullet's sequential-impulse contacts realise it: e along n to 0.002
// and the speeds after within a few hundredths of v (tests/physics/robot_impact_test.cc).
#pragma once

#include <Eigen/Core>
#include <string>

#include "models/field_spec.h"
#include "models/physics_params.h"
#include "models/robot_spec.h"
#include "physics/ball_state.h"

namespace foresight {

struct RobotImpactResult {
  bool touched = false;                           // the ball met the robot
  Eigen::Vector3d n_F = Eigen::Vector3d::Zero();  // first contact's normal, robot to ball
  BallState before;                               // the ball in the step before the impact
  BallState after;                                // ... and in the step after it
  double max_height_m = 0.0;  // highest the ball's lowest point rose above the carpet after it

  // Normal speed away from the robot after over normal speed into it before: the pair's
  // restitution as the solver realised it.
  double NormalRestitution() const;
  // Horizontal speed back along the roll after / the approach speed before.
  double ReboundRatio() const;
};

// Rolls the ball at speed_mps into `link` of `robot` standing at the origin of F facing +x.
RobotImpactResult RollIntoRobot(const FieldSpec& field, const PhysicsParams& params,
                                const Robot& robot, const std::string& link, double speed_mps,
                                double gap_m);

// The ball's velocities right after an instantaneous impact on a static body with normal n_F
// (from the body to the ball), restitution e and friction mu, for a ball of radius_m whose
// inertia is inertia_factor m r^2.
struct RigidImpact {
  Eigen::Vector3d v_F = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_F = Eigen::Vector3d::Zero();
};
RigidImpact PredictRigidImpact(const BallState& before, const Eigen::Vector3d& n_F, double radius_m,
                               double inertia_factor, double restitution, double friction);

}  // namespace foresight
