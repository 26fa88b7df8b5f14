// How fast a motion's joints really turn when it is played (physics/motion_playback.h), as a
// share of their motors' no-load speed: a joint carried on by the links swinging around it can
// turn faster than its own target asks (the NAO's knee behind a swinging thigh), which the
// targets' speed (models/kick_motion.h) does not show.
#pragma once

#include "models/physics_params.h"
#include "models/robot_spec.h"

namespace foresight {

// The largest |joint speed| / no-load speed of any motorised joint over the whole playback at
// speed_factor.
double FindPlayedSpeedShare(const Robot& robot, const KickMotion& motion,
                            const PhysicsParams& params, double speed_factor);

}  // namespace foresight
