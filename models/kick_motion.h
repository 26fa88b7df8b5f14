// A kick motion as data (models/robots/<robot>/motions/<kick>.json): joint keyframes over time
// and where the ball lies relative to the robot when the motion starts. Joints the motion does
// not name hold the robot's standing pose. Between keyframes the targets follow a cubic Hermite
// spline with Catmull-Rom tangents (zero velocity at the first and the last keyframe), so the
// motors get smooth position and velocity targets.
// A motion may start from its own stance ("stance": {"base_height_m", "pose_deg"}): a real robot
// stands up for a leg kick and lowers its chest for a head kick, while the base stays fixed in
// physics for the whole kick. The stance's joints replace robot.json's standing pose, its
// height robot.json's base_height_m; without one the kick starts from robot.json's stance.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "common/geometry.h"

namespace foresight {

struct KickKeyframe {
  double time_s = 0.0;
  std::vector<double> positions_rad;  // one per KickMotion::joints
};

struct KickStance {
  double base_height_m = 0.0;  // root link frame above the carpet; 0: robot.json's stance
  std::vector<std::pair<std::string, double>> pose_rad;  // joints set unlike robot.json's
  bool IsOwn() const { return base_height_m > 0.0; }
};

// How a robot standing on its own feet (a floating base, models/physics_params.h) keeps its
// balance through the kick: an open-loop weight shift played before the motion. Over shift_s
// the offsets ramp in along 3u^2 - 2u^3 (u = t / shift_s: zero speed at both ends), the robot
// then holds still for settle_s, and the motion plays with the offsets added to its targets
// (for joints the motion moves; a sum past the joint's limit stops at the limit) or to the
// stance (for the others). Hip roll and ankle roll of
// equal size and opposite sign on both legs move the torso sideways over the support foot with
// both soles level. A fixed base needs no balance and plays the motion without it.
struct KickBalance {
  double shift_s = 0.0;   // 0: no weight shift
  double settle_s = 0.0;
  std::vector<std::pair<std::string, double>> offsets_rad;  // joint -> offset
  bool Has() const { return shift_s > 0.0; }
  double DurationS() const { return shift_s + settle_s; }
  // The share of the offsets reached t_s after the shift starts (0 before, 1 after shift_s).
  double Share(double t_s) const;
};

struct KickMotion {
  std::string name;
  KickStance stance;
  KickBalance balance;  // played on a floating base only
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
