// Fitting the physical causes of a robot's kick spread to its real kicks: how far a team's robot
// misplaces itself and how much its kick motion's playback speed varies, chosen so that physics
// spreads its kicks as the robot did (`foresight calibrate --fit-variation --from-csv LOG`).
//
// Model. For small errors each launch quantity x (speed v, direction alpha) varies linearly with
// the causes, so its variance is a weighted sum of the causes' variances. The causes come in
// two groups scaled together: placement (sigma x, y, theta of robot.json's trial_variation,
// times s_p) and playback speed (its sigma times s_s):
//   Var x(s_p, s_s) = s_p^2 Var x|placement + s_s^2 Var x|playback,
// where Var x|placement and Var x|playback are measured in physics with one group at robot.json's
// magnitudes and the other switched off (same seeds: common random numbers). (s_p^2, s_s^2) is
// the non-negative least-squares fit of these equations to the observed variances of every
// kick, each weighted by 1 / observed variance (relative errors). The response is not linear
// (an off-centre toe sends the ball off much more than a centred one), so the fit is repeated
// with the group variances measured at the scales just fitted, until they settle. A last run at the
// fitted magnitudes checks the fit: its sigma_v and sigma_alpha beside the observed ones, and
// their RMS relative residual. The carpet's variation is left as it is: it does not change a
// launch. Physics never samples sigma_v or sigma_alpha themselves (docs/ARCHITECTURE.md).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "models/physics_params.h"
#include "models/robot_spec.h"
#include "validation/calibration.h"

namespace foresight {

struct LaunchSpread {
  double sigma_speed_mps = 0.0;
  double sigma_direction_rad = 0.0;
};

// The spread of a kick's launches as the fit compares it: robust sds (stats/statistics.h,
// RobustSd) of the speeds and of the directions around their circular mean. A glancing hit now
// and then gives a kick heavy tails (excess kurtosis 2-40 in the shipped calibrations), and with
// the plain sd one such trial in 300 moved the fit by a factor of two.
LaunchSpread SpreadOf(const std::vector<KickObservation>& observations);

// robot.json's variation with the placement sigmas times `placement` and the playback sigma
// times `playback`: the two groups the fit scales.
TrialVariation ScaledVariation(const TrialVariation& base, double placement, double playback);

struct VariationFitSettings {
  std::string robot;
  int trials = 400;  // per kick and run (three runs)
  std::uint64_t seed = 1;
  int threads = 0;
  std::optional<RobotBase> base;  // replaces the physics file's robot base
  // A progress reporter for each physics run of a kick (empty: none).
  std::function<std::function<void(int, int)>(const std::string& kick)> progress;
};

struct KickSpreadFit {
  std::string kick;
  LaunchSpread observed;
  LaunchSpread placement_only;  // physics, placement at robot.json's magnitudes, speed off
  LaunchSpread playback_only;   // physics, playback at robot.json's magnitude, placement off
  LaunchSpread fitted;          // physics at the fitted magnitudes
};

struct VariationFit {
  TrialVariation base;    // robot.json's
  double placement_scale = 0.0;
  double playback_scale = 0.0;
  TrialVariation fitted;  // base with the scales applied
  std::vector<KickSpreadFit> kicks;
  double rms_residual_rel = 0.0;  // over every kick's sigma_v and sigma_alpha
  int iterations = 0;             // linearisations until the scales settled
  // The playback spread the log asks for would drive a joint past its speed limit at 3 sigma:
  // it is held at the largest allowed, and the speed spread is then not reproduced.
  bool playback_at_limit = false;
  double fastest_playback = 0.0;  // the fastest the robot's motions may be played
};

// `observed`: each kick's spread (kicks the robot has no motion for are an InputError).
// Throws InputError when robot.json switches a group of causes off (nothing to scale).
VariationFit FitVariation(const VariationFitSettings& settings,
                          const std::map<std::string, LaunchSpread>& observed,
                          const std::filesystem::path& models_dir);

}  // namespace foresight
