#include "app/passing_physics.h"

#include <vector>

#include "common/error.h"
#include "models/model_paths.h"
#include "physics/physics_simulator.h"

namespace foresight {

PhysicsKickExecutor::PhysicsKickExecutor(const FieldSpec& field, const KickModel& kicks,
                                         const std::filesystem::path& models_dir,
                                         const std::filesystem::path& physics_file,
                                         std::optional<RobotBase> base)
    : field_(&field),
      kicks_(&kicks),
      robot_(LoadRobot(kicks.robot, models_dir)),
      physics_file_(physics_file.empty() ? DataFile(models_dir, DataFolder::kPhysics, field.name)
                                         : physics_file),
      params_(LoadPhysicsParams(physics_file_)) {
  if (base) params_.robot.base = *base;
  settled_ = SettleStances(robot_, params_);  // once, not per kick
  const PhysicsSimulator probe(
      MakePhysicsScene(field, params_, &robot_, {}, Vec2(0.0, 0.0), &settled_), kicks);
  for (int k = 0; k < static_cast<int>(kicks.kicks.size()); ++k) {
    if (!probe.HasMotion(k)) {
      throw InputError("--physics: kicks: robot '" + robot_.spec.name +
                       "' has no motion for kick '" +
                       kicks.kicks[static_cast<std::size_t>(k)].name + "'");
    }
  }
}

Outcome PhysicsKickExecutor::Execute(std::span<const Obstacle> robots, const DrawnState& state,
                                     const ConcreteAction& action) const {
  const std::vector<Obstacle> obstacles(robots.begin(), robots.end());
  const PhysicsSimulator simulator(
      MakePhysicsScene(*field_, params_, &robot_, obstacles, state.p_F_ball, &settled_), *kicks_);
  if (record_rate_hz_ <= 0.0) return simulator.Simulate(state, action);
  // Recording leaves the trial as it is (physics/scene_recorder.h): the same outcome.
  recorded_.push_back(simulator.Run(state, action, false, record_rate_hz_));
  return recorded_.back().outcome;
}

}  // namespace foresight
