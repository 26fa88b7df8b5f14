// Reading a robot's real kicks from CSV, for `foresight calibrate --from-csv`.
//
// One row per kick; the first line names the columns (any order):
//   kick                  name of the kick (as in the kick model), required
//   robot_x_m, robot_y_m, robot_theta_deg
//                         the robot's pose in F when it kicked, required
//   ball_x_m, ball_y_m    where the ball lay in F, required
//   launch_speed_mps, launch_direction_deg
//                         the ball's launch, direction in the robot frame (0 ahead, + left)
//   rest_x_m, rest_y_m    where the ball came to rest in F (it must not have touched anything)
// Each row needs the launch or the rest position (or both); cells of optional columns may be
// empty. Without a launch, the direction is the rest position's bearing in the robot frame and
// the speed is sqrt(2 a d) with the assumed deceleration a. The deceleration itself is fitted
// only from rows that have both (d = v0^2 / 2a).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "validation/calibration.h"

namespace foresight {

// Plausibility ranges of the CSV's numbers (assumptions, far beyond real values, far below what
// overflows a fit): positions within 100 m of the centre spot (an SPL field is 9 m long; a
// larger number is a unit error such as millimetres), angles within two turns, launch speeds
// up to 20 m/s (robot kicks reach about 5 m/s).
inline constexpr double kMaxObservedCoordinateM = 100.0;
inline constexpr double kMaxObservedAngleDeg = 720.0;
inline constexpr double kMaxObservedSpeedMps = 20.0;

struct ObservedKicks {
  std::vector<std::string> kick_names;  // in order of first appearance
  std::map<std::string, std::vector<KickObservation>> by_kick;
  int rows = 0;
  int speeds_from_rest = 0;  // rows whose speed came from the rest position
};

// Throws InputError "FILE: line N: COLUMN: problem" on bad input.
ObservedKicks ReadObservedKicks(const std::filesystem::path& file,
                                double assumed_deceleration_mps2);

}  // namespace foresight
