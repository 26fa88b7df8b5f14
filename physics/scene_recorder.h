// Records a physics trial as a scene trace (models/scene_trace.h) for the 3D viewer: at
// `rate_hz`, every link pose of the kicking robot, the ball's pose and spin and the phase; at
// every step, the contacts that pushed (the carpet's left out: the ball rolls on it and the feet stand on it
// all the time), summed per pair of bodies over a frame's interval so that a strike of a few
// milliseconds is never lost between frames.
//
// A trial without a recorder pays one null-pointer test per step (docs/PERFORMANCE.md, "Scene
// traces"). Frames are taken at the first step at or after each multiple of 1 / rate_hz, and at
// the trial's last step, so the trace ends where the ball rests.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "models/kick_motion.h"
#include "models/scene_trace.h"
#include "physics/physics_scene.h"

class btDispatcher;
class btRigidBody;

namespace foresight {

class KickingRobot;

class SceneRecorder {
 public:
  // Obstacles of the scene are recorded once, standing; `motion` names the kick's phases.
  SceneRecorder(const PhysicsScene& scene, const KickMotion& motion, double rate_hz);

  // After a kick phase step at t_s: `ball` may be null once the ball has left the kick world.
  // `motion_t_s` is the motion's own clock (t_s times the playback speed).
  void ObserveKick(double t_s, double motion_t_s, const KickingRobot& robot,
                   const btRigidBody* ball, btDispatcher& dispatcher);
  // After a roll phase step.
  void ObserveRoll(double t_s, const btRigidBody& ball, btDispatcher& dispatcher);
  // Takes the last step's frame if it was not taken yet; the trace is then complete.
  SceneTrace Finish();

 private:
  void AddContacts(btDispatcher& dispatcher, const KickingRobot* robot);
  bool FrameDue(double t_s) const;
  void TakeFrame(double t_s, int phase, const btRigidBody* ball, const KickingRobot* robot);
  void FlushContacts(double t_s);
  double NextFrameTime(double t_s) const;
  void AddLinks(const KickingRobot& robot, std::vector<ScenePose>& links);
  int KickPhase(double motion_t_s) const;

  const KickMotion& motion_;
  SceneTrace trace_;
  int roll_phase_ = 0;
  int stand_phase_ = 0;
  double next_frame_s_ = 0.0;
  // The last step, kept so Finish can take it as the final frame.
  SceneFrame last_;
  bool last_taken_ = true;
  // A floating robot standing on after the launch (ObserveKick without a ball).
  std::vector<SceneFrame> standing_;
  double next_standing_s_ = 0.0;
  std::vector<Eigen::Isometry3d> poses_scratch_;
  struct Sum {
    double impulse_Ns = 0.0;
    Eigen::Vector3d weighted_p_F = Eigen::Vector3d::Zero();
    double weight = 0.0;
  };
  std::map<std::pair<std::string, std::string>, Sum> pending_;
};

}  // namespace foresight
