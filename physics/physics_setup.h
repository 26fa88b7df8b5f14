// A situation's physics world, loaded from the shipped data: the robot of the situation's kick
// model, the physics parameters of its field (or a given file), the scene and the simulator.
// Physics plays the world as it is, so the state is the situation's mean, not a draw.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "models/physics_params.h"
#include "models/robot_spec.h"
#include "models/situation.h"
#include "physics/physics_simulator.h"

namespace foresight {

struct PhysicsSetup {
  Situation situation;
  Robot robot;
  std::filesystem::path physics_file;
  PhysicsParams params;
  DrawnState state;  // the situation's mean state
  std::optional<PhysicsSimulator> simulator;

  PhysicsSetup() = default;
  PhysicsSetup(const PhysicsSetup&) = delete;  // the scene points into it
  PhysicsSetup& operator=(const PhysicsSetup&) = delete;
};

// `physics_file` empty: MODELS/physics/<field>.json; `base` replaces the file's robot base
// (`--base`). `settled`, when given, are the robot's settled stances under these physics
// (SettleStances of an earlier setup of the same robot, field and physics file: a run over many
// situations settles once). Throws InputError on bad files.
std::unique_ptr<PhysicsSetup> LoadPhysicsSetup(Situation situation,
                                               const std::filesystem::path& models_dir,
                                               const std::filesystem::path& physics_file = {},
                                               std::optional<RobotBase> base = {},
                                               const SettledStances* settled = nullptr);

// InputError "WHERE: kicks: robot 'R' has no motion for kick 'K'" unless the robot has a motion
// for every kick of the situation's model (for runs that may execute any of them).
void RequireAllKickMotions(const PhysicsSetup& setup, const std::string& where);

}  // namespace foresight
