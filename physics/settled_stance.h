// A kick's weight shift played once on a bare carpet and kept (floating base): every trial of
// the kick then starts from this settled stance instead of playing the shift again.
//
// The shift (models/kick_motion.h, KickBalance) does not depend on anything a trial draws: the
// placement moves and turns the robot on a flat carpet, under which the dynamics are the same,
// and the playback speed applies to the motion, not to the shift. Playing it once per scene
// saves shift_s + settle_s of multibody steps per trial (1.5 s, 750 steps of 2 ms for the NAO).
// What a trial loses is only the ball and the goals during the shift: the shift moves the torso
// over the support foot and neither sole, so it touches neither.
#pragma once

#include <optional>
#include <vector>

#include "models/physics_params.h"
#include "models/robot_spec.h"
#include "physics/kicker_state.h"

namespace foresight {

struct SettledStance {
  KickerState state;           // relative to the root's pose before the shift
  double max_tilt_rad = 0.0;    // the torso's largest tilt while shifting and settling
  bool fell = false;            // it passed the physics file's fall tilt
};

// Stands `robot` in `motion`'s stance on a floating base on a bare carpet, plays the motion's
// balance (which it must have) and returns the state once it has settled.
SettledStance SettleBalance(const Robot& robot, const KickMotion& motion,
                            const PhysicsParams& params);

// Per motion of `robot`: its settled stance on a floating base when it has a balance; nothing
// for a fixed base or a motion without one.
using SettledStances = std::vector<std::optional<SettledStance>>;
SettledStances SettleStances(const Robot& robot, const PhysicsParams& params);

}  // namespace foresight
