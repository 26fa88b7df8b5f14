// Everything physics needs to know about one robot type besides its URDF
// (models/robots/<robot>/robot.json): how it stands, which kick motions it has, and how much a
// trial varies for physical reasons (placement relative to the ball, the motion's speed).
// Calibration measures sigma_v and sigma_alpha from these causes; nothing here is a kick sigma.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "models/kick_motion.h"
#include "models/motor_table.h"
#include "models/robot_model.h"

namespace foresight {

// Each trial draws these errors from normal distributions clipped at kClipSigmas (a robot never
// stands a metre off, a motion never plays at twice its speed).
struct TrialVariation {
  static constexpr double kClipSigmas = 3.0;
  double placement_sigma_x_m = 0.0;        // robot's placement error along R's x
  double placement_sigma_y_m = 0.0;        // ... along R's y
  double placement_sigma_theta_rad = 0.0;  // heading error
  double motion_speed_sigma_rel = 0.0;     // relative std. dev. of the motion's playback speed
  void Validate(const std::string& file) const;
  // The fastest a motion is ever played (1 = as written).
  double MaxSpeedFactor() const { return 1.0 + kClipSigmas * motion_speed_sigma_rel; }
};

// The launch a shipped kick must give standing on its own feet (optional per kick in
// robot.json: `launch_min_mps`, and `launch_max_mps` when the kick has a ceiling): the
// requirement the robot's kicks are held to (tests/physics/floating_falls_test.cc).
struct LaunchTarget {
  double min_mps = 0.0;
  std::optional<double> max_mps;
};

struct RobotSpec {
  std::string name;
  std::filesystem::path urdf_file;  // resolved
  double base_height_m = 0.0;       // height of the root link's frame above the carpet
  std::vector<std::pair<std::string, double>> standing_pose_rad;  // joints not named: 0
  std::vector<std::pair<std::string, std::filesystem::path>> kick_motion_files;  // resolved
  std::vector<std::pair<std::string, LaunchTarget>> launch_targets;  // kicks that have one
  TrialVariation variation;
  MotorTable motors;  // joint name -> its motor's torque-speed line
  // On a floating base these joints get motors besides the motion's and its balance's (the
  // legs, which carry the robot); the others are welded at the stance (a fixed base welds
  // every joint the motion does not move).
  std::vector<std::string> support_joints;
  // Optional: the name prefixes of the left and the right side's joints ("L", "R" for the
  // NAO's LHipRoll and RHipRoll), which pair them for mirroring a motion (tools/motion_mirror.h).
  // Empty: the robot's motions cannot be mirrored.
  std::string left_prefix, right_prefix;
};

RobotSpec LoadRobotSpec(const std::filesystem::path& file);

// A variation file: what `foresight calibrate --fit-variation` writes ({"robot", "source",
// "spread_measure", "trial_variation": {robot.json's keys}, "fit"}), read by `calibrate
// --variation` and `simulate --variation` in place of robot.json's trial_variation. Throws
// InputError when the file is for another robot than `robot`.
TrialVariation LoadTrialVariation(const std::filesystem::path& file, const std::string& robot);

struct Robot;

// The fastest a joint turns in a motion played as written, sampled every millisecond: the joint
// (index into model.joints; -1 if no joint moves), when, how fast, and as a share of its limit.
struct PeakJointSpeed {
  int joint = -1;
  double t_s = 0.0;
  double speed_radps = 0.0;
  double share = 0.0;
};
PeakJointSpeed FindPeakJointSpeed(const KickMotion& motion, const RobotModel& model);

// The fastest playback factor at which no motion of the robot exceeds a joint's speed limit.
double FastestAllowedPlayback(const Robot& robot);

// A robot ready for physics: its spec, body and kick motions, checked against each other
// (every joint a motion or the standing pose names exists and is revolute; every revolute joint
// has a motor that can reach its velocity limit; every target lies
// within the joint's limits, a motion's stance included; no motion, played at the fastest speed a trial draws, asks a joint
// for more than its velocity limit).
struct Robot {
  RobotSpec spec;
  RobotModel model;
  std::vector<KickMotion> motions;  // in the order of spec.kick_motion_files
  std::vector<MotorLine> motors;    // model.joints order; fixed joints: an empty line

  std::optional<int> FindMotion(const std::string& kick_name) const;
  // The standing position of every joint of `model`, in model.joints order.
  std::vector<double> StandingPositions() const;
  // Where a kick starts: the standing pose with the motion's own stance, if it has one, and
  // the height of the root link's frame above the carpet.
  std::vector<double> StandingPositions(const KickMotion& motion) const;
  double BaseHeightM(const KickMotion& motion) const;
};

// Loads models_dir/robots/<name>/robot.json and everything it names.
Robot LoadRobot(const std::string& name, const std::filesystem::path& models_dir);

// Loads the motion of kick `kick_name` from `file` and checks it against `robot` as LoadRobot
// checks the shipped ones (its name, joints, limits, speeds and weight shift); InputError
// "FILE: FIELD: problem" otherwise. A motion search starts from such a file.
KickMotion LoadRobotKickMotion(const Robot& robot, const std::string& kick_name,
                               const std::filesystem::path& file);
// The checks of LoadRobotKickMotion but the name's, on a motion made in memory; `where` begins
// the message.
void CheckRobotKickMotion(const Robot& robot, const KickMotion& motion, const std::string& where);

// MODELS_DIR/robots/NAME/robot.json; InputError listing the robots there when NAME is none.
std::filesystem::path RobotSpecFile(const std::string& name,
                                    const std::filesystem::path& models_dir);

}  // namespace foresight
