// Calibrating a kick's noise model (models/kick_model.h) from observed kicks: physics trials or
// a robot's real kicks.
//
// The model (Mellmann & Schlotter, sec. III-B): launch speed v0 ~ N(mu_v, sigma_v^2) and
// direction alpha ~ N(mu_alpha, sigma_alpha^2) in the robot frame. Speeds get the normal fit
// with exact intervals and an Anderson-Darling test that is valid with estimated parameters;
// directions get the circular mean and circular standard deviation sqrt(-2 ln R) with bootstrap
// intervals, and the same test on the directions unwrapped around their mean (the model treats
// alpha as a normal). The rolling deceleration comes from the balls' speed over time
// (validation/deceleration_fit.h) or, for observed kicks, from launch speeds and roll distances.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/random.h"
#include "models/kick_model.h"
#include "physics/trial.h"
#include "stats/goodness_of_fit.h"
#include "stats/statistics.h"
#include "validation/deceleration_fit.h"

namespace foresight {

// The seed of kick `kick_index`'s physics trials in a calibration seeded with `seed`: each kick
// has its own, so calibrating one kick alone gives the same numbers as calibrating all.
inline std::uint64_t CalibrationSeed(std::uint64_t seed, int kick_index) {
  return StreamKey(seed, static_cast<std::uint64_t>(kick_index));
}

// One observed kick. `rolling` (speed over time while the ball rolls freely) may be empty;
// roll_distance_m is the straight distance from the launch to the rest, meaningful only when
// has_roll_distance (the ball came to rest without touching anything).
struct KickObservation {
  double launch_speed_mps = 0.0;
  double launch_direction_rad = 0.0;  // robot frame
  std::vector<SpeedSample> rolling;
  double roll_distance_m = 0.0;
  bool has_roll_distance = false;
  // A logged kick without a launch: the speed is sqrt(2 a d) from the roll distance, for an
  // assumed deceleration until calibration has fitted one.
  bool speed_from_rest = false;
  // Physics only, with a roll distance: how far from where the ball lay free rolling started
  // (the trial's launch point).
  double launch_offset_m = 0.0;
  bool has_launch_offset = false;
};

// Where the coarse roll's free rolling starts for one kick (models/kick_model.h),
// fitted so that the coarse model's mean rest distance matches the observed one with the
// calibrated deceleration a: offset = mean(D_i - v_i^2 / 2a) over the kicks that rested without
// touching anything, D_i the distance from where the ball lay to where it rested (the launch
// offset plus the roll from the launch point). Clamped at 0 (free rolling cannot start behind
// the ball). launch_point_m is the launch points' own mean distance: the offset's physical
// reading, equal to the fit when the calibrated deceleration is the one the balls rolled at.
struct LaunchOffsetFit {
  int kicks = 0;
  double offset_m = 0.0;  // what the kick model gets
  double unclamped_offset_m = 0.0;
  double standard_error_m = 0.0;  // of the mean
  double launch_point_m = 0.0;    // mean measured distance to the launch point
  double rest_distance_m = 0.0;   // mean D_i
};

struct CalibrationSettings {
  double confidence = 0.95;
  int resamples = 2000;  // bootstrap resamples
  std::uint64_t seed = 1;
  double normality_level = 0.05;  // below this p-value the report says the normal model fails
};

struct KickCalibration {
  std::string kick;
  int observations = 0;
  NormalFit speed;
  NormalityTest speed_normality;
  std::vector<QqPoint> speed_qq;
  CircularFit direction;
  std::vector<double> direction_unwrapped_rad;  // around the circular mean
  NormalityTest direction_normality;
  std::vector<QqPoint> direction_qq;             // radians
  std::optional<DecelerationFit> deceleration;   // this kick's balls alone
  std::optional<LaunchOffsetFit> launch_offset;  // physics: with the pooled deceleration
};

// Throws InputError when there are fewer than 8 observations (too few for the test).
KickCalibration CalibrateKick(const std::string& kick, std::span<const KickObservation> kicks,
                              const CalibrationSettings& settings);

// The deceleration of all given kicks' balls together: from trajectories when any observation
// has them, else from roll distances (d = v0^2 / 2a, least squares through the origin with a
// bootstrap interval); nothing when neither is known.
std::optional<DecelerationFit> FitPooledDeceleration(std::span<const KickObservation> kicks,
                                                     const CalibrationSettings& settings);

// The launch offset of one kick's observations for the deceleration a; nothing when fewer than 2
// of them have a launch offset and a roll distance (e.g. a real robot's log: its rows hold no
// launch point).
std::optional<LaunchOffsetFit> FitLaunchOffset(std::span<const KickObservation> kicks,
                                               double deceleration_mps2);

// What a physics trial shows of its kick. The rolling samples run from the launch until the ball
// leaves the carpet (bounces), slows below min_speed_mps (below about 0.2 m/s the
// contact jitters and the rest tail begins; both bias the slope low) or the
// trace ends; a trial whose ball touched a post, net or robot gives no rolling samples.
KickObservation ObservationOf(const TrialResult& trial, double ball_radius_m,
                              double min_speed_mps = 0.2);

// `base` with the calibrated kicks' speed, direction and sigmas replaced (and the launch offset
// where one was fitted), and the deceleration when one is given. Kicks not in `calibrated` keep
// their values.
KickModel ApplyCalibration(const KickModel& base, std::span<const KickCalibration> calibrated,
                           const std::optional<DecelerationFit>& deceleration);

}  // namespace foresight
