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
// the speed is sqrt(2 a d) with the assumed deceleration a (calibrate re-derives it with the
// fitted deceleration: RederiveSpeedsFromRest). The deceleration itself is fitted only from rows
// that have both (d = v0^2 / 2a).
//
// The file is CSV after RFC 4180: a cell may be quoted ("forward", "1.5"), a quoted cell may hold
// commas, doubled quotes and line breaks; spaces around a cell are dropped; LF or CRLF ends a row.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "models/kick_model.h"
#include "validation/calibration.h"

namespace foresight {

// Plausibility ranges of the CSV's numbers (assumptions, far beyond real values, far below what
// overflows a fit): positions within 100 m of the centre spot (an SPL field is 9 m long; a
// larger number is a unit error such as millimetres), angles within two turns, launch speeds
// up to 20 m/s (robot kicks reach about 5 m/s).
inline constexpr double kMaxObservedCoordinateM = 100.0;
inline constexpr double kMaxObservedAngleDeg = 720.0;
inline constexpr double kMaxObservedSpeedMps = 20.0;

// How far a row's launch direction may lie from its rest position's bearing, in the kick's
// direction sigma of the kick model (assumption: the coarse model rolls the ball straight, so
// the two agree but for measurement error; a difference beyond 3 sigma is rarer than 3 in 1000
// draws of the kick itself, so the row's two halves do not describe one kick).
inline constexpr double kMaxLaunchRestSigmas = 3.0;

// One row as the file gave it, for the unit and consistency checks.
struct ObservedRow {
  int line = 0;  // where the row starts in the file
  std::string kick;
  std::optional<double> launch_direction_deg;  // robot frame, as written
  std::optional<double> rest_bearing_deg;      // the rest position's bearing, robot frame
};

struct ObservedKicks {
  std::vector<std::string> kick_names;  // in order of first appearance
  std::map<std::string, std::vector<KickObservation>> by_kick;
  int rows = 0;
  int speeds_from_rest = 0;  // rows whose speed came from the rest position
  std::vector<ObservedRow> row_list;  // every row, in file order
};

// Throws InputError "FILE: line N: COLUMN: problem" on bad input.
ObservedKicks ReadObservedKicks(const std::filesystem::path& file,
                                double assumed_deceleration_mps2);

// Units and consistency against the kick model the log is fitted to; throws InputError
// "FILE: line N: launch_direction_deg: ..." naming the first row that fails:
// - a row with a launch and a rest whose launch direction lies more than kMaxLaunchRestSigmas
//   of the kick's sigma_direction from the rest's bearing (said to look like radians when the
//   number read as radians agrees with the bearing);
// - a kick whose launch directions all lie within +-pi and whose mean misses the model's
//   direction by more than kMaxLaunchRestSigmas sigma, while the mean read as radians meets it
//   (a side kick logged as 1.48 instead of 85 deg).
// Kicks the model does not know are left to the caller.
void CheckObservedKicks(const ObservedKicks& kicks, const KickModel& model,
                        const std::filesystem::path& file);

// Speeds of rows that had only a rest position, again from sqrt(2 a (d - offset)) with the
// deceleration a the calibration fitted and the kick's launch offset (free rolling starts there).
void RederiveSpeedsFromRest(std::vector<KickObservation>& kicks, double deceleration_mps2,
                            double launch_offset_m);

}  // namespace foresight
