// The kick action model (models/kicks/*.json), after Mellmann & Schlotter, sec. III-B:
// a kick launches the ball with speed v0 ~ N(speed_mps, sigma_speed_mps^2) in direction
// alpha ~ N(direction_rad, sigma_direction_rad^2), alpha in the robot frame R (0 = straight
// ahead, +pi/2 = to the left). The ball then decelerates at rolling_deceleration_mps2.
//
// launch_offset_m is where free rolling starts, measured from where the ball lay along
// the launch direction: a kicked ball first slides (physics: about 5 cm for the NAO's forward
// kick) and only then rolls at v0. The coarse roll covers the offset before it decelerates.
// Calibration fits it (foresight calibrate, physics mode); the paper's models leave it 0.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace foresight {

struct KickSpec {
  std::string name;
  double speed_mps = 0.0;
  double sigma_speed_mps = 0.0;
  double direction_rad = 0.0;
  double sigma_direction_rad = 0.0;
  double launch_offset_m = 0.0;  // optional in the files: 0 when absent
};

// The kick index of the `none` action: no kick, the ball stays where it lies.
inline constexpr int kNoKick = -1;

struct KickModel {
  std::string robot;
  double rolling_deceleration_mps2 = 0.0;
  std::vector<KickSpec> kicks;

  // Index of the kick called `name`, if there is one.
  std::optional<int> Find(const std::string& name) const;
  // The name of kick `kick_index`, or "none" for kNoKick.
  std::string NameOf(int kick_index) const;
  // "forward, side_kick_left, ..." for messages and help texts.
  std::string Names() const;
  void Validate() const;
};

KickModel LoadKickModel(const std::filesystem::path& file);
// The same from text that is not (yet) a file, e.g. a model about to be written, read back
// first so that nothing the reader would refuse is ever written; `origin` names it in messages.
KickModel ParseKickModel(std::string_view text, const std::string& origin);

// The largest kick speed (and speed spread) a data file may give: far above any robot's kick,
// a guard against a unit slip (assumption).
inline constexpr double kMaxKickSpeedMps = 50.0;

// The decimals a kick-model file keeps: speeds (m/s), lengths (m) and the deceleration (m/s^2)
// to 4, angles (deg) to 2. A report that sets a fit beside a committed model prints both with
// these, so both sides are rounded alike and the committed figure is shown as it is stored.
inline constexpr int kKickFileSpeedDecimals = 4;
inline constexpr int kKickFileAngleDecimals = 2;

// The model as a kick-model file that LoadKickModel reads back: speeds rounded to 0.1 mm/s,
// angles to 0.01 degree, the deceleration to 0.1 mm/s^2 (so files diff cleanly).
std::string KickModelJson(const KickModel& model, std::string_view notes);

}  // namespace foresight
