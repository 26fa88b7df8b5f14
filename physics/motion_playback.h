// A kick motion played alone: the robot on a fixed base, no ball, no carpet, the motion's joints
// under their motors. What the motion itself asks of the motors, before any contact loads them.
#pragma once

#include <functional>

#include "models/physics_params.h"
#include "models/robot_spec.h"
#include "physics/kicking_robot.h"

namespace foresight {

// Plays `motion` at speed_factor (> 1: faster) to its end; after every kick time step,
// each_step(kicker, t_s) looks at the robot.
void PlayMotionAlone(const Robot& robot, const KickMotion& motion, const PhysicsParams& params,
                     double speed_factor,
                     const std::function<void(const KickingRobot&, double)>& each_step);

}  // namespace foresight
