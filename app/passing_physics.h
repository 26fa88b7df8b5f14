// `foresight experiment passing --physics`: the match's kicks executed in the Bullet scene
// (physics/) instead of drawn from the kick model. Each kick builds the static scene of its
// moment (the field, the other robots as the robot model standing where they are, facing the
// ball) and runs one whole physics trial of the kick's motion, perturbed from the action's
// stream (physics/trial.h); the match replays the outcome's path in time as for the coarse model.
//
// Approximated: the robots that keep moving while the ball rolls are discs in the match, not
// bodies in the Bullet world (the ball is stopped dead by them there); the kicker is placed at the
// ball by the motion's own placement, not where the match's disc stood; the coarse launch the
// match drew is ignored (physics draws its own perturbations).
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "match/kick_executor.h"
#include "models/kick_model.h"
#include "models/physics_params.h"
#include "models/robot_spec.h"
#include "physics/settled_stance.h"
#include "physics/trial.h"

namespace foresight {

class PhysicsKickExecutor final : public KickExecutor {
 public:
  // Loads the robot of `kicks` and the physics file (empty: MODELS/physics/<field>.json), `base`
  // replacing its robot base; InputError when a kick of `kicks` has no motion.
  PhysicsKickExecutor(const FieldSpec& field, const KickModel& kicks,
                      const std::filesystem::path& models_dir,
                      const std::filesystem::path& physics_file,
                      std::optional<RobotBase> base = {});
  Outcome Execute(std::span<const Obstacle> robots, const DrawnState& state,
                  const ConcreteAction& action) const override;
  const std::filesystem::path& physics_file() const { return physics_file_; }
  RobotBase base() const { return params_.robot.base; }  // as played: --base or the file's
  const Robot& robot() const { return robot_; }

  // From now on every kick's whole trial is kept, its scene recorded at rate_hz, in the order
  // of the calls (recorded()): for the 3D viewer of one trial played again. An executor that
  // records must not be shared between threads.
  void Record(double rate_hz) { record_rate_hz_ = rate_hz; }
  const std::vector<TrialResult>& recorded() const { return recorded_; }

 private:
  const FieldSpec* field_;
  const KickModel* kicks_;
  Robot robot_;
  std::filesystem::path physics_file_;
  PhysicsParams params_;
  SettledStances settled_;  // settled once for every kick's scene (floating base)
  double record_rate_hz_ = 0.0;
  mutable std::vector<TrialResult> recorded_;  // only while recording (single-threaded)
};

}  // namespace foresight
