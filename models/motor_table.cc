#include "models/motor_table.h"

#include <algorithm>
#include <optional>

#include "common/checks.h"
#include "common/error.h"

namespace foresight {
namespace {

// Published no-load speeds are rounded to 4-5 digits, and URDFs quote them converted: the NAO's
// arm type B gives 412.19 deg/s = 7.19407 rad/s, its URDF 7.19442. A motor this much slower than
// the joint's limit still counts as reaching it.
constexpr double kRoundingShare = 1e-4;

}  // namespace

MotorLine::Range MotorLine::TorqueRangeNm(double speed_radps) const {
  const double share = speed_radps / no_load_speed_radps;
  // Forward (positive torque) the motor helps a positive speed less the faster it turns, and
  // brakes a negative one with at most the stall torque; backward mirrors it.
  return {-stall_torque_nm * std::clamp(1.0 + share, 0.0, 1.0),
          stall_torque_nm * std::clamp(1.0 - share, 0.0, 1.0)};
}

MotorTable ReadMotorTable(const JsonObject& motors) {
  motors.RejectUnknownKeys({"types", "joints"});
  const JsonObject types = motors.Object("types");
  std::vector<std::pair<std::string, MotorLine>> lines;
  for (const std::string& type : types.Keys()) {
    if (type == "notes") continue;
    const JsonObject item = types.Object(type);
    item.RejectUnknownKeys({"stall_torque_nm", "no_load_speed_radps", "source"});
    MotorLine line{item.Number("stall_torque_nm"), item.Number("no_load_speed_radps")};
    if (!(line.stall_torque_nm > 0.0)) {
      item.Fail("stall_torque_nm", "must be > 0, got " + FormatNumber(line.stall_torque_nm));
    }
    if (!(line.no_load_speed_radps > 0.0)) {
      item.Fail("no_load_speed_radps",
                "must be > 0, got " + FormatNumber(line.no_load_speed_radps));
    }
    if (item.String("source").empty()) item.Fail("source", "must say where the figures come from");
    lines.emplace_back(type, line);
  }
  const JsonObject joints = motors.Object("joints");
  MotorTable table;
  for (const std::string& joint : joints.Keys()) {
    if (joint == "notes") continue;
    const std::string type = joints.String(joint);
    const auto found = std::find_if(lines.begin(), lines.end(),
                                    [&](const auto& entry) { return entry.first == type; });
    if (found == lines.end()) joints.Fail(joint, "'" + type + "' is not one of motors.types");
    table.emplace_back(joint, found->second);
  }
  return table;
}

std::vector<MotorLine> JointMotors(const MotorTable& table, const RobotModel& model,
                                   const std::string& file) {
  const std::string field = file + ": motors.joints.";
  std::vector<MotorLine> motors(model.joints.size());
  std::vector<bool> named(model.joints.size(), false);
  for (const auto& [joint_name, line] : table) {
    const std::optional<int> index = model.FindJoint(joint_name);
    if (!index || model.joints[*index].kind != RobotJoint::Kind::kRevolute) {
      throw InputError(field + joint_name + ": not a revolute joint of " + model.source.string());
    }
    const RobotJoint& joint = model.joints[*index];
    if (line.no_load_speed_radps < joint.velocity_radps * (1.0 - kRoundingShare)) {
      throw InputError(field + joint_name + ": the motor's no-load speed " +
                       FormatNumber(line.no_load_speed_radps) +
                       " rad/s lies below the joint's velocity limit " +
                       FormatNumber(joint.velocity_radps) + " rad/s");
    }
    motors[*index] = line;
    named[*index] = true;
  }
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    if (model.joints[j].kind == RobotJoint::Kind::kRevolute && !named[j]) {
      throw InputError(field + model.joints[j].name +
                       ": missing (every revolute joint needs "
                       "its motor)");
    }
  }
  return motors;
}

}  // namespace foresight
