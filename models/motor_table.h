// The robot's motors as physics drives them (robot.json "motors"): each joint's DC motor behind
// its gear, reduced to the two figures a motor table gives at the joint, the stall torque and the
// no-load speed. Between them the torque a motor can apply falls on a line,
// tau <= tau_stall (1 - w / w0): a brushed DC motor at full voltage, whose back-EMF grows with
// speed. Which motor and gear drives which joint is data with its source (NAO: Aldebaran's motor
// tables; AIBO: no table is published, an assumption says how the figures were derived).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "common/json_reader.h"
#include "models/robot_model.h"

namespace foresight {

struct MotorLine {
  double stall_torque_nm = 0.0;      // at the joint, at rest
  double no_load_speed_radps = 0.0;  // at the joint, without load

  // The torques (N m, signed like the joint's axis) the motor can apply at joint speed
  // speed_radps (signed): along the motion the line, falling to 0 at the no-load speed and
  // beyond; against the motion (braking) at most the stall torque, the stall current being the
  // most the drive lets through in either direction (assumption).
  struct Range {
    double min_nm = 0.0;
    double max_nm = 0.0;
  };
  Range TorqueRangeNm(double speed_radps) const;
};

// The motor table as read: joint name -> its motor's line, in the file's (sorted) order.
using MotorTable = std::vector<std::pair<std::string, MotorLine>>;

// Reads the "motors" object: {"types": {TYPE: {"stall_torque_nm", "no_load_speed_radps",
// "source"}}, "joints": {JOINT: TYPE}}. Throws InputError naming the file and field for a
// missing or non-positive figure, an empty source, or a joint naming an unknown type.
MotorTable ReadMotorTable(const JsonObject& motors);

// The motor of every joint of `model` (model.joints order; fixed joints get an empty line).
// Throws "FILE: motors.joints: ..." when a revolute joint has no motor, a named joint is not a
// revolute joint of the model, or a motor's no-load speed lies below the joint's velocity limit
// (the motions are checked against that limit, so the motor must be able to reach it).
std::vector<MotorLine> JointMotors(const MotorTable& table, const RobotModel& model,
                                   const std::string& file);

}  // namespace foresight
