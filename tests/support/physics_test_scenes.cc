#include "tests/support/physics_test_scenes.h"

#include "tests/support/test_situations.h"

namespace foresight::testing {

std::unique_ptr<PhysicsFixtureData> LoadPhysicsFixture(const std::string& field_name,
                                                       bool uniform_carpet,
                                                       const std::string& robot_name) {
  auto data = std::make_unique<PhysicsFixtureData>();
  data->field = LoadFieldSpec(ModelsDir() / "fields" / (field_name + ".json"));
  data->params = LoadPhysicsParams(ModelsDir() / "physics" / (field_name + ".json"));
  // The fixed base, the cheap approximation (a tenth of a floating trial's cost), not the files'
  // floating one: these scenes test a trial's parts (contacts, motors, strikes, placements,
  // recordings), which the fixed base plays without the balance; the floating tests ask for the
  // floating base themselves (floating_kick_test.cc, floating_falls_test.cc).
  data->params.robot.base = RobotBase::kFixed;
  if (uniform_carpet) {
    data->params.carpet.deceleration_sigma_rel = 0.0;
    data->params.carpet.patch_sigma_rel = 0.0;
  }
  if (!robot_name.empty())
    data->robot = std::make_unique<Robot>(LoadRobot(robot_name, ModelsDir()));
  return data;
}

PhysicsScene SceneOf(const PhysicsFixtureData& data, const std::vector<Obstacle>& obstacles,
                     const Vec2& p_F_ball) {
  return MakePhysicsScene(data.field, data.params, data.robot.get(), obstacles, p_F_ball);
}

}  // namespace foresight::testing
