// The watch for a fall after the launch (floating base; phases.h).
//
// Once the ball has launched, the kick phase hands it to the roll phase as it was then: the
// ball's outcome is fixed. What is left is whether the robot falls before it has stood its
// balance's settle time after its motion. WatchForFall steps the robot on as the kick did and
// ends at the stand's end, at a fall, or once the robot stands provably still after its motion
// (StandsStill, by the physics file's `watch`, models/physics_params.h): its motors then hold
// constant targets, and a robot at rest with its centre of mass inside its support stays at
// rest. Up to that stop every step is the one the full watch takes, so a fall and the largest
// tilt are those of the full watch until then (docs/PHYSICS.md, "The watch after the launch").
#pragma once

#include <Eigen/Core>
#include <span>

#include "models/kick_motion.h"
#include "models/physics_params.h"

class btDispatcher;

namespace foresight {

class BulletWorld;
class KickingRobot;
class SceneRecorder;

// The watch's stretch of the kick phase's clock.
struct WatchSpan {
  double t_start_s = 0.0;     // the launch
  double motion_end_s = 0.0;  // the motion's end, at its playback speed
  double stand_end_s = 0.0;   // ... plus the balance's settle time
  double speed_factor = 1.0;  // the motion's playback speed
};

struct WatchEnd {
  bool fell = false;
  double max_tilt_rad = 0.0;  // the largest tilt, the one before the watch included
  double t_s = 0.0;           // when the watch ended
  bool still = false;         // it ended because the robot stood still
};

// Steps `world` (the ball already removed) from span.t_start_s; `max_tilt_rad` is the largest
// tilt so far.
WatchEnd WatchForFall(BulletWorld& world, KickingRobot& robot, const KickMotion& motion,
                      const WatchSpan& span, const PhysicsParams& params, double max_tilt_rad,
                      SceneRecorder* recorder = nullptr);

// Whether the robot, as it moves now, is still by `watch`: every joint, its base's speed and
// rate below the thresholds, its torso under still_tilt_rad, and its centre of mass at least
// still_support_margin_m inside its support (SupportMarginM).
bool StandsStill(const KickingRobot& robot, btDispatcher& dispatcher, const WatchParams& watch);

// How far the robot's centre of mass, seen from above, lies inside the convex hull of its
// contact points with the carpet that carried a load in the last step (m; negative outside,
// -infinity with fewer than three such points not on a line).
double SupportMarginM(const KickingRobot& robot, btDispatcher& dispatcher);

// How far p lies inside the convex hull of `points` (negative outside; -infinity for a hull
// without area).
double HullMarginM(std::span<const Eigen::Vector2d> points, const Eigen::Vector2d& p);

}  // namespace foresight
