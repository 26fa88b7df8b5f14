// The physical world around the ball for the Bullet ground truth (models/physics/<field>.json):
// the carpet's rolling resistance and its variation, materials, and the simulation's steps.
//
// The carpet's `rolling_deceleration_mps2` is the truth physics rolls on. The kick model's
// rolling_deceleration_mps2 (models/kicks/*.json) is what the coarse model believes; calibration
// measures the former and writes it into the latter. Both ship at mu * g = 0.0275 * 9.81.
// Every number comes from the file; the structs hold no defaults of their own.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace foresight {

struct CarpetParams {
  double rolling_deceleration_mps2 = 0.0;  // a of a freely rolling ball on a uniform carpet
  double deceleration_sigma_rel = 0.0;     // per trial: relative std. dev. of a (wear, humidity)
  double patch_size_m = 0.0;               // the carpet is laid in square patches ...
  double patch_sigma_rel = 0.0;            // ... each with its own factor on a (fixed layout)
  std::uint64_t patch_seed = 0;            // the layout of the patches
  double friction = 0.0;                   // Coulomb friction ball-carpet (sliding after a kick)
  double restitution = 0.0;
};

struct MaterialParams {
  double ball_restitution = 0.0;
  double ball_friction = 0.0;
  double post_restitution = 0.0;
  double net_restitution = 0.0;
  double net_friction = 0.0;
  double robot_restitution = 0.0;  // robot links and obstacle robots
  double robot_friction = 0.0;
  double net_thickness_m = 0.0;
};

struct StepParams {
  double kick_time_step_s = 0.0;  // while the kicking robot is simulated
  double near_time_step_s = 0.0;  // rolling near a post, net or obstacle
  double free_time_step_s = 0.0;  // rolling on open carpet
  double max_kick_time_s = 0.0;   // after that the kick phase ends, touched or not
  double max_roll_time_s = 0.0;   // a ball still moving then is reported as not settled
  double rest_speed_mps = 0.0;    // below this (and on the carpet) the ball rests
  int solver_iterations = 0;
};

// Joint motors follow the motion's targets as velocity constraints (Bullet's
// btMultiBodyJointMotor): desired joint speed = position_gain * error / dt + velocity_gain *
// (target speed - speed), limited by the URDF joint's effort.
struct MotorParams {
  double position_gain = 0.0;
  double velocity_gain = 0.0;
};

struct PhysicsParams {
  CarpetParams carpet;
  MotorParams motors;
  MaterialParams materials;
  StepParams steps;

  // Throws InputError "field: must be ..., got VALUE" for the first bad value.
  void Validate() const;
};

PhysicsParams LoadPhysicsParams(const std::filesystem::path& file);

}  // namespace foresight
