#include "physics/physics_setup.h"

#include "common/error.h"
#include "models/model_paths.h"

namespace foresight {

std::unique_ptr<PhysicsSetup> LoadPhysicsSetup(Situation situation,
                                               const std::filesystem::path& models_dir,
                                               const std::filesystem::path& physics_file,
                                               std::optional<RobotBase> base,
                                               const SettledStances* settled) {
  auto setup = std::make_unique<PhysicsSetup>();
  setup->situation = std::move(situation);
  const Situation& s = setup->situation;
  setup->robot = LoadRobot(s.kicks.robot, models_dir);
  setup->physics_file = physics_file.empty()
                            ? DataFile(models_dir, DataFolder::kPhysics, s.field.name)
                            : physics_file;
  setup->params = LoadPhysicsParams(setup->physics_file);
  if (base) setup->params.robot.base = *base;
  setup->state = DrawnState{s.state.robot, s.state.MeanBallInField()};
  setup->simulator.emplace(
      MakePhysicsScene(s.field, setup->params, &setup->robot, s.obstacles, setup->state.p_F_ball,
                       settled),
      s.kicks);
  return setup;
}

void RequireAllKickMotions(const PhysicsSetup& setup, const std::string& where) {
  const KickModel& model = setup.situation.kicks;
  for (int k = 0; k < static_cast<int>(model.kicks.size()); ++k) {
    if (!setup.simulator->HasMotion(k)) {
      throw InputError(where + ": kicks: robot '" + setup.robot.spec.name +
                       "' has no motion for kick '" +
                       model.kicks[static_cast<std::size_t>(k)].name + "'");
    }
  }
}

}  // namespace foresight
