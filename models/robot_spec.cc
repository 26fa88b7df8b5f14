// robot.json, and a Robot assembled from it: spec, URDF body and kick motions, checked against
// each other so physics can drive every joint target without further checks.
#include "models/robot_spec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/checks.h"
#include "common/error.h"
#include "common/geometry.h"
#include "common/json_reader.h"
#include "models/kick_model.h"
#include "models/model_paths.h"

namespace foresight {
namespace {

// Joint targets within this much of a limit count as within it (degrees in files, radians here).
constexpr double kLimitToleranceRad = 1e-9;

std::filesystem::path Resolve(const std::filesystem::path& dir, const std::string& reference) {
  const std::filesystem::path path(reference);
  return path.is_absolute() ? path : (dir / path).lexically_normal();
}

TrialVariation ReadVariation(const JsonObject& item) {
  item.RejectUnknownKeys({"placement_sigma_x_m", "placement_sigma_y_m", "placement_sigma_theta_deg",
                          "motion_speed_sigma_rel"});
  TrialVariation variation;
  variation.placement_sigma_x_m = item.Number("placement_sigma_x_m");
  variation.placement_sigma_y_m = item.Number("placement_sigma_y_m");
  variation.placement_sigma_theta_rad = item.Number("placement_sigma_theta_deg") * kDegToRad;
  variation.motion_speed_sigma_rel = item.Number("motion_speed_sigma_rel");
  return variation;
}

// The revolute joint `joint_name` of `model`; throws "FILE: FIELD: ..." when it is missing or
// fixed.
const RobotJoint& RevoluteJoint(const RobotModel& model, const std::string& joint_name,
                                const std::string& file, const std::string& field) {
  const std::optional<int> index = model.FindJoint(joint_name);
  if (!index) {
    throw InputError(file + ": " + field + ": '" + joint_name + "' is not a joint of " +
                     model.source.string());
  }
  const RobotJoint& joint = model.joints[*index];
  if (joint.kind != RobotJoint::Kind::kRevolute) {
    throw InputError(file + ": " + field + ": '" + joint_name + "' is a fixed joint in " +
                     model.source.string());
  }
  return joint;
}

// `label` names the target in the file: "keyframes[2].positions_deg[1] (LKneePitch)".
void RequireWithinLimits(const RobotJoint& joint, double position_rad, const std::string& file,
                         const std::string& label) {
  if (position_rad >= joint.lower_rad - kLimitToleranceRad &&
      position_rad <= joint.upper_rad + kLimitToleranceRad) {
    return;
  }
  throw InputError(file + ": " + label + ": " + FormatNumber(position_rad * kRadToDeg) +
                   " deg is outside the joint's limits [" +
                   FormatNumber(joint.lower_rad * kRadToDeg) + ", " +
                   FormatNumber(joint.upper_rad * kRadToDeg) + "] deg");
}

void CheckStandingPose(const Robot& robot, const std::string& spec_file) {
  for (const auto& [joint_name, position_rad] : robot.spec.standing_pose_rad) {
    const std::string field = "standing_pose_deg." + joint_name;
    const RobotJoint& joint = RevoluteJoint(robot.model, joint_name, spec_file, field);
    RequireWithinLimits(joint, position_rad, spec_file, field);
  }
}

// The motion's targets sampled this finely find the spline's fastest point to well under 1 %.
constexpr double kSpeedCheckStepS = 0.001;

// No joint may be asked to turn faster than its URDF velocity limit, at the fastest playback;
// the message names the worst excess (joint, time, speed).
void CheckJointSpeeds(const KickMotion& motion, const RobotModel& model, double max_factor,
                      const std::string& file) {
  const PeakJointSpeed peak = FindPeakJointSpeed(motion, model);
  if (peak.joint < 0 || peak.share * max_factor <= 1.0) return;
  const RobotJoint& joint = model.joints[peak.joint];
  char message[256];
  std::snprintf(message, sizeof message,
                "keyframes: %s must turn at %.3f rad/s at t = %.3f s when played %.3g times as "
                "fast (the fastest trial), over its limit of %.3f rad/s",
                joint.name.c_str(), peak.speed_radps * max_factor, peak.t_s, max_factor,
                joint.velocity_radps);
  throw InputError(file + ": " + message);
}

void CheckMotion(const KickMotion& motion, const RobotModel& model, double max_factor,
                 const std::string& file) {
  for (const auto& [joint_name, position_rad] : motion.stance.pose_rad) {
    const std::string field = "stance.pose_deg." + joint_name;
    RequireWithinLimits(RevoluteJoint(model, joint_name, file, field), position_rad, file, field);
  }
  for (std::size_t j = 0; j < motion.joints.size(); ++j) {
    const std::string joint_field = "joints[" + std::to_string(j) + "]";
    const RobotJoint& joint = RevoluteJoint(model, motion.joints[j], file, joint_field);
    for (std::size_t k = 0; k < motion.keyframes.size(); ++k) {
      const std::string label = "keyframes[" + std::to_string(k) + "].positions_deg[" +
                                std::to_string(j) + "] (" + joint.name + ")";
      RequireWithinLimits(joint, motion.keyframes[k].positions_rad[j], file, label);
    }
  }
  CheckJointSpeeds(motion, model, max_factor, file);
}

// The balance's joints exist and are revolute, and the stance with its offsets stays within
// the joints' limits. (During the motion a target the offset pushes past a limit stops at it:
// physics/kicking_robot.cc.)
void CheckBalance(const Robot& robot, const KickMotion& motion, const std::string& file) {
  const std::vector<double> stance = robot.StandingPositions(motion);
  for (const auto& [joint_name, offset_rad] : motion.balance.offsets_rad) {
    const std::string field = "balance.offsets_deg." + joint_name;
    const RobotJoint& joint = RevoluteJoint(robot.model, joint_name, file, field);
    const double q = stance[*robot.model.FindJoint(joint_name)] + offset_rad;
    RequireWithinLimits(joint, q, file, field + " (with the stance)");
  }
}

void CheckSupportJoints(const Robot& robot, const std::string& file) {
  for (std::size_t j = 0; j < robot.spec.support_joints.size(); ++j) {
    RevoluteJoint(robot.model, robot.spec.support_joints[j], file,
                  "support_joints[" + std::to_string(j) + "]");
  }
}

}  // namespace

PeakJointSpeed FindPeakJointSpeed(const KickMotion& motion, const RobotModel& model) {
  const std::size_t n = motion.joints.size();
  std::vector<double> q(n), qdot(n);
  PeakJointSpeed peak;
  for (double t = 0.0; t <= motion.DurationS(); t += kSpeedCheckStepS) {
    motion.Sample(t, q, qdot);
    for (std::size_t j = 0; j < n; ++j) {
      const int index = *model.FindJoint(motion.joints[j]);
      const double share = std::abs(qdot[j]) / model.joints[index].velocity_radps;
      if (share <= peak.share) continue;
      peak = {index, t, std::abs(qdot[j]), share};
    }
  }
  return peak;
}

double FastestAllowedPlayback(const Robot& robot) {
  double fastest = std::numeric_limits<double>::infinity();
  for (const KickMotion& motion : robot.motions) {
    const PeakJointSpeed peak = FindPeakJointSpeed(motion, robot.model);
    if (peak.share > 0.0) fastest = std::min(fastest, 1.0 / peak.share);
  }
  return fastest;
}

void TrialVariation::Validate(const std::string& file) const {
  WithFile(file, [&] {
    RequireNonNegative("trial_variation.placement_sigma_x_m", placement_sigma_x_m);
    RequireNonNegative("trial_variation.placement_sigma_y_m", placement_sigma_y_m);
    RequireNonNegative("trial_variation.placement_sigma_theta_deg",
                       placement_sigma_theta_rad * kRadToDeg);
    RequireNonNegative("trial_variation.motion_speed_sigma_rel", motion_speed_sigma_rel);
    // A placement error larger than a robot, or a heading error beyond a half turn, is no error
    // of walking up to a ball.
    RequireInRange("trial_variation.placement_sigma_x_m", placement_sigma_x_m, 0.0,
                   kMaxRobotLengthM);
    RequireInRange("trial_variation.placement_sigma_y_m", placement_sigma_y_m, 0.0,
                   kMaxRobotLengthM);
    RequireInRange("trial_variation.placement_sigma_theta_deg",
                   placement_sigma_theta_rad * kRadToDeg, 0.0, 180.0);
  });
  if (!(motion_speed_sigma_rel < 0.5)) {
    throw InputError(file + ": trial_variation.motion_speed_sigma_rel: must be < 0.5, got " +
                     FormatNumber(motion_speed_sigma_rel));
  }
}

RobotSpec LoadRobotSpec(const std::filesystem::path& file) {
  const JsonDocument doc = JsonDocument::Load(file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys(
      {"name", "urdf", "base_height_m", "standing_pose_deg", "kicks", "trial_variation", "motors",
       "support_joints", "mirror_prefixes"});
  const std::filesystem::path dir = file.parent_path();
  const std::string where = file.string();
  RobotSpec spec;
  spec.name = root.String("name");
  if (spec.name.empty()) root.Fail("name", "must not be empty");
  const std::string urdf = root.String("urdf");
  if (urdf.empty()) root.Fail("urdf", "must name the robot's URDF file");
  spec.urdf_file = Resolve(dir, urdf);
  WithFile(where, [&] { NamedFile("urdf", spec.urdf_file); });
  spec.base_height_m = root.Number("base_height_m");
  WithFile(where, [&] {
    RequirePositive("base_height_m", spec.base_height_m);
    RequireInRange("base_height_m", spec.base_height_m, 0.0, kMaxRobotLengthM);
  });

  const JsonObject pose = root.Object("standing_pose_deg");
  for (const std::string& joint : pose.Keys()) {
    if (joint == "notes") continue;  // allowed everywhere (json_reader.h)
    if (joint.empty()) pose.Fail(joint, "joint names must not be empty");
    spec.standing_pose_rad.emplace_back(joint, pose.Number(joint) * kDegToRad);  // files: degrees
  }

  if (!root.Has("kicks")) root.Fail("kicks", "missing");
  const std::vector<JsonObject> kicks = root.ObjectArray("kicks");
  if (kicks.empty()) root.Fail("kicks", "must list at least one kick");
  for (const JsonObject& kick : kicks) {
    kick.RejectUnknownKeys({"name", "motion", "launch_min_mps", "launch_max_mps"});
    const std::string name = kick.String("name");
    if (name.empty()) kick.Fail("name", "must not be empty");
    for (const auto& [other, unused] : spec.kick_motion_files) {
      if (other == name) kick.Fail("name", "duplicate '" + name + "'");
    }
    const std::string motion = kick.String("motion");
    if (motion.empty()) kick.Fail("motion", "must name the kick's motion file");
    spec.kick_motion_files.emplace_back(name, Resolve(dir, motion));
    WithFile(where, [&] {
      NamedFile(kick.PathOf("motion"), spec.kick_motion_files.back().second);
    });
    if (kick.Has("launch_max_mps") && !kick.Has("launch_min_mps")) {
      kick.Fail("launch_max_mps", "needs launch_min_mps");
    }
    if (kick.Has("launch_min_mps")) {
      LaunchTarget target;
      target.min_mps = kick.Number("launch_min_mps");
      if (!(target.min_mps > 0.0 && target.min_mps <= kMaxKickSpeedMps)) {
        kick.Fail("launch_min_mps", "must be in (0, " + FormatNumber(kMaxKickSpeedMps) + "], got " +
                                        FormatNumber(target.min_mps));
      }
      if (kick.Has("launch_max_mps")) {
        target.max_mps = kick.Number("launch_max_mps");
        if (!(*target.max_mps > target.min_mps && *target.max_mps <= kMaxKickSpeedMps)) {
          kick.Fail("launch_max_mps", "must be above launch_min_mps and at most " +
                                          FormatNumber(kMaxKickSpeedMps) + ", got " +
                                          FormatNumber(*target.max_mps));
        }
      }
      spec.launch_targets.emplace_back(name, target);
    }
  }

  spec.variation = ReadVariation(root.Object("trial_variation"));
  spec.variation.Validate(where);
  spec.motors = ReadMotorTable(root.Object("motors"));
  if (root.Has("support_joints")) spec.support_joints = root.StringArray("support_joints");
  if (root.Has("mirror_prefixes")) {
    const std::vector<std::string> prefixes = root.StringArray("mirror_prefixes");
    if (prefixes.size() != 2 || prefixes[0].empty() || prefixes[1].empty() ||
        prefixes[0] == prefixes[1]) {
      root.Fail("mirror_prefixes", "must list two different non-empty prefixes, left then right");
    }
    spec.left_prefix = prefixes[0];
    spec.right_prefix = prefixes[1];
  }
  return spec;
}

TrialVariation LoadTrialVariation(const std::filesystem::path& file, const std::string& robot) {
  const JsonDocument document = JsonDocument::Load(file);
  const JsonObject root = document.Root();
  root.RejectUnknownKeys({"robot", "source", "spread_measure", "trial_variation", "fit"});
  const std::string for_robot = root.String("robot");
  if (for_robot != robot) {
    root.Fail("robot", "the variation is for '" + for_robot + "', not for '" + robot + "'");
  }
  TrialVariation variation = ReadVariation(root.Object("trial_variation"));
  variation.Validate(file.string());
  return variation;
}

std::optional<int> Robot::FindMotion(const std::string& kick_name) const {
  for (std::size_t i = 0; i < spec.kick_motion_files.size(); ++i) {
    if (spec.kick_motion_files[i].first == kick_name) return static_cast<int>(i);
  }
  return std::nullopt;
}

std::vector<double> Robot::StandingPositions() const {
  std::vector<double> positions(model.joints.size(), 0.0);
  for (const auto& [joint_name, position_rad] : spec.standing_pose_rad) {
    if (const std::optional<int> index = model.FindJoint(joint_name)) {
      positions[*index] = position_rad;
    }
  }
  return positions;
}

std::vector<double> Robot::StandingPositions(const KickMotion& motion) const {
  std::vector<double> positions = StandingPositions();
  for (const auto& [joint_name, position_rad] : motion.stance.pose_rad) {
    if (const std::optional<int> index = model.FindJoint(joint_name)) {
      positions[*index] = position_rad;
    }
  }
  return positions;
}

double Robot::BaseHeightM(const KickMotion& motion) const {
  return motion.stance.IsOwn() ? motion.stance.base_height_m : spec.base_height_m;
}

std::filesystem::path RobotSpecFile(const std::string& name,
                                    const std::filesystem::path& models_dir) {
  const std::filesystem::path robots_dir = DataFolderPath(models_dir, DataFolder::kRobots);
  const std::filesystem::path spec_file = robots_dir / name / "robot.json";
  std::error_code ec;
  if (name.empty() || name.find('/') != std::string::npos ||
      !std::filesystem::is_regular_file(spec_file, ec)) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(robots_dir, ec)) {
      if (std::filesystem::is_regular_file(entry.path() / "robot.json", ec)) {
        names.push_back(entry.path().filename().string());
      }
    }
    std::sort(names.begin(), names.end());
    std::string available;
    for (const std::string& robot : names) available += (available.empty() ? "" : ", ") + robot;
    throw InputError("no robot '" + name + "' in " + robots_dir.string() +
                     " (available: " + (available.empty() ? "none" : available) + ")");
  }
  return spec_file;
}

Robot LoadRobot(const std::string& name, const std::filesystem::path& models_dir) {
  const std::filesystem::path spec_file = RobotSpecFile(name, models_dir);
  Robot robot;
  robot.spec = LoadRobotSpec(spec_file);
  if (robot.spec.name != name) {
    throw InputError(spec_file.string() + ": name: must be '" + name +
                     "' (the robot's folder), got '" + robot.spec.name + "'");
  }
  robot.model = LoadRobotModel(robot.spec.urdf_file);
  CheckStandingPose(robot, spec_file.string());
  robot.motors = JointMotors(robot.spec.motors, robot.model, spec_file.string());
  CheckSupportJoints(robot, spec_file.string());
  for (const auto& [kick_name, motion_file] : robot.spec.kick_motion_files) {
    robot.motions.push_back(LoadRobotKickMotion(robot, kick_name, motion_file));
  }
  return robot;
}

KickMotion LoadRobotKickMotion(const Robot& robot, const std::string& kick_name,
                               const std::filesystem::path& file) {
  KickMotion motion = LoadKickMotion(file);
  if (motion.name != kick_name) {
    throw InputError(file.string() + ": name: must be '" + kick_name + "' (the kick of robot '" +
                     robot.spec.name + "'), got '" + motion.name + "'");
  }
  CheckRobotKickMotion(robot, motion, file.string());
  return motion;
}

void CheckRobotKickMotion(const Robot& robot, const KickMotion& motion, const std::string& where) {
  CheckMotion(motion, robot.model, robot.spec.variation.MaxSpeedFactor(), where);
  CheckBalance(robot, motion, where);
}

}  // namespace foresight
