#include "models/physics_params.h"

#include "common/checks.h"
#include "common/error.h"
#include "common/json_reader.h"

namespace foresight {

void PhysicsParams::Validate() const {
  RequireInRange("carpet.rolling_deceleration_mps2", carpet.rolling_deceleration_mps2, 1e-3, 10.0);
  RequireInRange("carpet.deceleration_sigma_rel", carpet.deceleration_sigma_rel, 0.0, 0.3);
  RequireInRange("carpet.patch_size_m", carpet.patch_size_m, 0.05, 100.0);
  RequireInRange("carpet.patch_sigma_rel", carpet.patch_sigma_rel, 0.0, 0.3);
  RequireInRange("carpet.friction", carpet.friction, 0.0, 5.0);
  RequireInRange("carpet.restitution", carpet.restitution, 0.0, 1.0);
  RequireInRange("materials.ball_restitution", materials.ball_restitution, 0.0, 1.0);
  RequireInRange("materials.ball_friction", materials.ball_friction, 0.0, 5.0);
  RequireInRange("materials.post_restitution", materials.post_restitution, 0.0, 1.0);
  RequireInRange("materials.net_restitution", materials.net_restitution, 0.0, 1.0);
  RequireInRange("materials.net_friction", materials.net_friction, 0.0, 5.0);
  RequireInRange("materials.robot_restitution", materials.robot_restitution, 0.0, 1.0);
  RequireInRange("materials.robot_friction", materials.robot_friction, 0.0, 5.0);
  RequireInRange("materials.net_thickness_m", materials.net_thickness_m, 0.005, 0.5);
  RequireInRange("motors.position_gain", motors.position_gain, 0.0, 1.0);
  RequireInRange("motors.velocity_gain", motors.velocity_gain, 0.0, 10.0);
  RequireInRange("steps.kick_time_step_s", steps.kick_time_step_s, 1e-5, 0.01);
  RequireInRange("steps.near_time_step_s", steps.near_time_step_s, 1e-5, 0.01);
  RequireInRange("steps.free_time_step_s", steps.free_time_step_s, steps.near_time_step_s, 0.05);
  RequireInRange("steps.max_kick_time_s", steps.max_kick_time_s, 0.1, 60.0);
  RequireInRange("steps.max_roll_time_s", steps.max_roll_time_s, 1.0, 3600.0);
  RequireInRange("steps.rest_speed_mps", steps.rest_speed_mps, 1e-5, 0.1);
  RequireInRange("steps.solver_iterations", steps.solver_iterations, 1, 1000);
}

namespace {

CarpetParams ReadCarpet(const JsonObject& o) {
  o.RejectUnknownKeys({"rolling_deceleration_mps2", "deceleration_sigma_rel", "patch_size_m",
                       "patch_sigma_rel", "patch_seed", "friction", "restitution"});
  CarpetParams c;
  c.rolling_deceleration_mps2 = o.Number("rolling_deceleration_mps2");
  c.deceleration_sigma_rel = o.Number("deceleration_sigma_rel");
  c.patch_size_m = o.Number("patch_size_m");
  c.patch_sigma_rel = o.Number("patch_sigma_rel");
  const int seed = o.Integer("patch_seed");
  if (seed < 0) o.Fail("patch_seed", "must be >= 0, got " + std::to_string(seed));
  c.patch_seed = static_cast<std::uint64_t>(seed);
  c.friction = o.Number("friction");
  c.restitution = o.Number("restitution");
  return c;
}

MaterialParams ReadMaterials(const JsonObject& o) {
  o.RejectUnknownKeys({"ball_restitution", "ball_friction", "post_restitution", "net_restitution",
                       "net_friction", "robot_restitution", "robot_friction", "net_thickness_m"});
  MaterialParams m;
  m.ball_restitution = o.Number("ball_restitution");
  m.ball_friction = o.Number("ball_friction");
  m.post_restitution = o.Number("post_restitution");
  m.net_restitution = o.Number("net_restitution");
  m.net_friction = o.Number("net_friction");
  m.robot_restitution = o.Number("robot_restitution");
  m.robot_friction = o.Number("robot_friction");
  m.net_thickness_m = o.Number("net_thickness_m");
  return m;
}

MotorParams ReadMotors(const JsonObject& o) {
  o.RejectUnknownKeys({"position_gain", "velocity_gain"});
  MotorParams m;
  m.position_gain = o.Number("position_gain");
  m.velocity_gain = o.Number("velocity_gain");
  return m;
}

StepParams ReadSteps(const JsonObject& o) {
  o.RejectUnknownKeys({"kick_time_step_s", "near_time_step_s", "free_time_step_s",
                       "max_kick_time_s", "max_roll_time_s", "rest_speed_mps",
                       "solver_iterations"});
  StepParams s;
  s.kick_time_step_s = o.Number("kick_time_step_s");
  s.near_time_step_s = o.Number("near_time_step_s");
  s.free_time_step_s = o.Number("free_time_step_s");
  s.max_kick_time_s = o.Number("max_kick_time_s");
  s.max_roll_time_s = o.Number("max_roll_time_s");
  s.rest_speed_mps = o.Number("rest_speed_mps");
  s.solver_iterations = o.Integer("solver_iterations");
  return s;
}

}  // namespace

PhysicsParams LoadPhysicsParams(const std::filesystem::path& file) {
  JsonDocument doc = JsonDocument::Load(file);
  JsonObject root = doc.Root();
  root.RejectUnknownKeys({"carpet", "motors", "materials", "steps"});
  PhysicsParams params;
  params.carpet = ReadCarpet(root.Object("carpet"));
  params.motors = ReadMotors(root.Object("motors"));
  params.materials = ReadMaterials(root.Object("materials"));
  params.steps = ReadSteps(root.Object("steps"));
  WithFile(file.string(), [&] { params.Validate(); });
  return params;
}

}  // namespace foresight
