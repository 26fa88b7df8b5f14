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
#include <optional>
#include <string>
#include <string_view>

namespace foresight {

struct CarpetParams {
  double rolling_deceleration_mps2 = 0.0;  // a of a freely rolling ball on a uniform carpet
  double deceleration_sigma_rel = 0.0;     // per trial: relative std. dev. of a (wear, humidity)
  double patch_size_m = 0.0;               // the carpet is laid in square patches ...
  double patch_sigma_rel = 0.0;            // ... each with its own factor on a (fixed layout)
  std::uint64_t patch_seed = 0;            // the layout of the patches
};

// One coefficient per pair of bodies the ball can touch. "foot" is every link of the kicking
// robot (its foot, or its head in a head kick); "robot" is the standing obstacle robots.
struct BallPairs {
  double carpet = 0.0;
  double post = 0.0;  // posts and crossbar
  double net = 0.0;
  double foot = 0.0;
  double robot = 0.0;
};

// Bullet combines two bodies' coefficients as their product; physics/ gives the ball 1 and
// every other body the pair's value, so each contact realises exactly the value here.
struct MaterialParams {
  BallPairs restitution;  // normal separation speed / approach speed
  BallPairs friction;     // Coulomb coefficients
  double net_thickness_m = 0.0;
};

// The longest kick phase a physics file may time (steps.max_kick_time_s): a kick motion may last
// no longer either (models/kick_motion.h), so no motion file makes a trial run for hours.
inline constexpr double kMaxKickTimeLimitS = 60.0;

struct StepParams {
  double kick_time_step_s = 0.0;  // while the kicking robot is simulated
  double near_time_step_s = 0.0;  // rolling near a post, net or obstacle, ...
  double max_overlap_m = 0.0;     // ... or shorter, so one step moves it at most this far
  double free_time_step_s = 0.0;  // rolling on open carpet, ...
  double slow_speed_mps = 0.0;     // ... and once slower than this ...
  double slow_time_step_s = 0.0;   // ... with this step
  double max_kick_time_s = 0.0;   // after that the kick phase ends, touched or not
  double max_roll_time_s = 0.0;   // a ball still moving then is reported as not settled
  double rest_speed_mps = 0.0;    // below this (and on the carpet) the ball rests
  // Before the motion ends, a touched ball counts as launched only once its speed would carry
  // it this far (v^2 / 2a): a slower one is still within reach of the rest of the motion.
  double min_launch_roll_m = 0.0;
  int solver_iterations = 0;
  // Contacts approaching slower than this do not bounce (Bullet's restitution threshold): a
  // ball resting on the carpet must not jitter.
  double restitution_threshold_mps = 0.0;
};

// Joint motors follow the motion's targets as velocity constraints (Bullet's
// btMultiBodyJointMotor): desired joint speed = position_gain * error / dt + velocity_gain *
// (target speed - speed), its torque limited by the joint motor's torque-speed line
// (models/motor_table.h).
struct MotorParams {
  double position_gain = 0.0;
  double velocity_gain = 0.0;
};

// How the kicking robot stands. kFixed bolts its torso to the world (the fast approximation:
// no balance, the robot touches only the ball); kFloating stands it on its own feet on the
// carpet, every link colliding with the carpet, posts, nets, obstacle robots and the ball, and
// plays each motion's weight shift first (models/kick_motion.h, KickBalance).
enum class RobotBase { kFixed, kFloating };
std::string_view RobotBaseName(RobotBase base);
std::optional<RobotBase> ParseRobotBase(std::string_view name);
std::string RobotBaseList();  // "fixed, floating"

// The robot's own contacts (floating base): its links against the carpet, posts, nets and the
// obstacle robots. Bullet's product of two bodies' coefficients does not apply: these pairs get
// exactly these values. The ball's contacts with the robot keep the materials' foot pair.
struct RobotContactParams {
  RobotBase base = RobotBase::kFixed;
  double friction = 0.0;     // Coulomb coefficient, sole on carpet
  double restitution = 0.0;
  double fall_tilt_rad = 0.0;  // the torso tilted further from upright than this: it fell
};

// The watch for a fall after the launch (floating base; physics/fall_watch.h). The ball has gone
// to the roll phase and its outcome is fixed; the robot is stepped on only to tell whether it
// falls, until its motion has ended and it has stood the balance's settle time. The watch ends
// early once the robot stands provably still: its motion over, every joint and its base slower
// than these speeds, its torso under `still_tilt_rad` and its centre of mass at least
// `still_support_margin_m` inside the polygon of its loaded contacts with the carpet, all for
// `still_time_s` without a break. Its motors then hold constant targets: a robot at rest in such
// a pose stays there.
struct WatchParams {
  double still_time_s = 0.0;
  double still_joint_speed_radps = 0.0;
  double still_base_speed_mps = 0.0;
  double still_base_rate_radps = 0.0;
  double still_tilt_rad = 0.0;
  double still_support_margin_m = 0.0;
};

struct PhysicsParams {
  CarpetParams carpet;
  RobotContactParams robot;
  WatchParams watch;
  MotorParams motors;
  MaterialParams materials;
  StepParams steps;

  // Throws InputError "field: must be ..., got VALUE" for the first bad value.
  void Validate() const;
};

PhysicsParams LoadPhysicsParams(const std::filesystem::path& file);

}  // namespace foresight
