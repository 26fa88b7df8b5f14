// Physics scenes shared by the physics tests and benchmarks: the shipped SPL field and carpet,
// with the carpet's random variation switched off where a test needs the exact deceleration.
#pragma once

#include <memory>
#include <vector>

#include "models/field_spec.h"
#include "models/physics_params.h"
#include "models/robot_spec.h"
#include "models/situation.h"
#include "physics/physics_scene.h"

namespace foresight::testing {

struct PhysicsFixtureData {
  FieldSpec field;
  PhysicsParams params;
  std::unique_ptr<Robot> robot;  // null unless asked for
};

// The shipped field and physics of `field_name` with the robot on the fixed base;
// `uniform_carpet` zeroes the carpet's per-trial and per-patch variation. `robot_name` empty: no
// robot.
std::unique_ptr<PhysicsFixtureData> LoadPhysicsFixture(const std::string& field_name,
                                                       bool uniform_carpet,
                                                       const std::string& robot_name = "");

PhysicsScene SceneOf(const PhysicsFixtureData& data, const std::vector<Obstacle>& obstacles = {},
                     const Vec2& p_F_ball = Vec2::Zero());

}  // namespace foresight::testing
