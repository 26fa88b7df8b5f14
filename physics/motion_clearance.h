// How close a kick motion takes the robot's body to the carpet. The kicking robot's links touch
// only the ball (physics/bullet_world.h: its base is fixed, so carpet contacts would only fight
// the motors), so nothing in a trial stops a foot or paw that a motion drives below the carpet:
// it passes through it, and a swing that a real robot could not make can launch the ball. This
// measures it by forward kinematics of the motion's targets (the motors track them closely,
// tests/physics/joint_motor_test.cc), with the base at the kick's stance's height.
// Clearance is the height of the lowest point of any collision shape over the carpet (z = 0):
// negative means that much below it.
#pragma once

#include <Eigen/Geometry>
#include <string>

#include "models/kick_motion.h"
#include "models/robot_spec.h"

namespace foresight {

// The lowest point of a link's collision shapes, z in frame F, for the link's pose pose_F_L
// (mesh vertices, box corners, sphere and z-axis cylinder surfaces).
double LowestPointZ(const RobotLink& link, const Eigen::Isometry3d& pose_F_L);

struct MotionClearance {
  double lowest_m = 0.0;  // height of the lowest point over the whole motion
  double t_s = 0.0;       // when, in the motion as written
  int link = -1;          // which link (index into model.links)
  std::string link_name;
};

// The motion's targets sampled every step_s from start to end (every other joint at the
// kick's stance), the base level at the stance's height (Robot::BaseHeightM).
MotionClearance FindMotionClearance(const Robot& robot, const KickMotion& motion,
                                    double step_s = 0.001);

// The same over the links the motion moves only (the swinging leg, not the support foot that
// stands on the carpet) and only between the motion's first and last inner keyframes (the lift
// from the stance and the set-down start and end with the foot on the carpet; a motion of two
// keyframes is taken whole): the motion search's clearance rule (tools/motion_search.h).
// Infinite (link -1) when the motion moves no link with collision shapes.
MotionClearance FindSwingClearance(const Robot& robot, const KickMotion& motion,
                                   double step_s = 0.001);

}  // namespace foresight
