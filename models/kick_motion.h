// A kick motion as data (models/robots/<robot>/motions/<kick>.json): joint keyframes over time
// and where the ball lies relative to the robot when the motion starts. Joints the motion does
// not name hold the robot's standing pose. Between keyframes the targets follow a cubic Hermite
// spline with Catmull-Rom tangents (zero velocity at the first and the last keyframe), so the
// motors get smooth position and velocity targets.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "common/geometry.h"

namespace foresight {

struct KickKeyframe {
  double time_s = 0.0;
  std::vector<double> positions_rad;  // one per KickMotion::joints
};

struct KickMotion {
  std::string name;
  Vec2 p_R_ball{0.0, 0.0};  // nominal ball centre in the robot frame R at the motion's start
  std::vector<std::string> joints;
  std::vector<KickKeyframe> keyframes;  // time_s strictly increasing, the first at 0

  double DurationS() const { return keyframes.back().time_s; }
  // Target positions and velocities of `joints` at time t_s (clamped to [0, duration]).
  void Sample(double t_s, std::span<double> q_rad, std::span<double> qdot_radps) const;
  void Validate(const std::string& file) const;
};

KickMotion LoadKickMotion(const std::filesystem::path& file);

}  // namespace foresight
