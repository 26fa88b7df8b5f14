// The kinds of check of `foresight check`, each with its own typed settings, and running one.
// Each struct below is one kind: its kKind is the spec's "kind" and its fields are the spec's
// keys of the same names (validation/physics_checks.h reads them and lists them per kind).
//
// Validate() throws InputError "FIELD: must be ..., got VALUE" (common/checks.h) when a value is
// out of its range; the loader calls it and puts "FILE: checks[i]." before the field, so a
// running check can trust its settings.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "physics/impact_probe.h"

namespace foresight {

struct CheckResult {
  std::string name;
  std::string kind;
  bool passed = false;
  std::string detail;  // one line: what was measured against what was expected
  double time_s = 0.0;
};

inline constexpr int kMinCheckTrials = 2;
inline constexpr int kMaxCheckTrials = 100000;
inline constexpr int kMaxCheckPhases = 1000;
inline constexpr double kMaxCheckSeed = 9007199254740992.0;  // 2^53: a JSON number holds it exactly
// Limits of meaning, not of the physics: a free roll faster than any kick of the shipped robots
// (the rebound checks' own limit) and a line error larger than the field.
inline constexpr double kMaxCheckSpeedMps = 20.0;
inline constexpr double kMaxCheckLateralM = 100.0;

// A ball set rolling on a uniform carpet without edges (the field's physics file, its variation
// switched off) stops at v^2 / 2a within max_error_rel and within max_lateral_m of its line.
struct FreeRollCheck {
  static constexpr std::string_view kKind = "free_roll";
  std::string field;  // a field name or file, as a situation names it
  double speed_mps = 0.0;
  double heading_deg = 0.0;
  double max_error_rel = 0.0;
  double max_lateral_m = 0.0;
  void Validate() const;
};

// A fast ball fired at a post, the back net or a side net from outside (physics/impact_probe.h),
// with the contact at `phases` evenly spread points of a time step, never gets deeper into it
// than max_penetration_steps times the distance it rolls in one step at that speed.
struct NoTunnellingCheck {
  static constexpr std::string_view kKind = "no_tunnelling";
  std::string field;
  ImpactTarget target = ImpactTarget::kPost;
  double speed_mps = 0.0;
  int phases = 0;
  double max_penetration_steps = 0.0;
  void Validate() const;
};

// A ball rolled at a post or net at each speed, with the contact at `phases` points of a time
// step, comes back at e * v (e from the field's physics file, v the speed it arrived with)
// within max_error_rel of e * v or min_error_mps, whichever is larger.
struct ReboundCheck {
  static constexpr std::string_view kKind = "rebound";
  std::string field;
  ImpactTarget target = ImpactTarget::kPost;
  std::vector<double> speeds_mps;
  int phases = 0;
  double max_error_rel = 0.0;
  double min_error_mps = 0.0;
  void Validate() const;
};

// A ball rolled head-on at a standing robot's link at each speed (physics/robot_impact.h, which
// says why the answer is not e * v): Bullet realises the pair's restitution e (ball_robot of the
// field's physics file) along the contact normal within max_error_rel of e, and the ball's
// speeds just after the impact, back along its roll and upwards, lie within max_error_rel of
// the approach speed of what rigid-body impact theory predicts for that normal, e and the pair's
// friction. The hop (the ball's highest rise) is reported.
struct RobotReboundCheck {
  static constexpr std::string_view kKind = "robot_rebound";
  std::string field;
  std::string robot;
  std::string link;
  std::vector<double> speeds_mps;
  double max_error_rel = 0.0;
  void Validate() const;
};

// A robot's kick, trials times from its calibration situation (seed 1): every trial touches
// the ball and the circular mean direction lies within max_error_deg of the kick model's.
struct KickDirectionCheck {
  static constexpr std::string_view kKind = "kick_direction";
  std::string robot;
  std::string kick;
  std::string kicks;  // the kick model: a name or file
  int trials = 0;
  double max_error_deg = 0.0;
  void Validate() const;
};

// Calibrating every kick of a robot from trials physics kicks (seeded as `calibrate --seed`
// seeds them) gives v0, sigma_v and sigma_alpha within band_rel (relative) and alpha within
// band_deg of the committed kick model. With the calibration's own seed and trials it is a
// drift guard (the numbers are reproduced exactly unless physics changed); with another seed
// it also tests the sampling error.
struct CalibrationBandCheck {
  static constexpr std::string_view kKind = "calibration_band";
  std::string robot;
  std::string kicks;
  int trials = 0;
  std::uint64_t seed = 0;  // at most kMaxCheckSeed
  double band_rel = 0.0;
  double band_deg = 0.0;
  void Validate() const;
};

// A fidelity run on a situation set: the mean Kendall tau-b of the coarse model is at least
// min_tau_b and its mean regret at most max_regret.
struct FidelityFloorCheck {
  static constexpr std::string_view kKind = "fidelity_floor";
  std::string situations;  // a situation set's name or file
  std::string kicks;
  int trials = 0;
  double min_tau_b = 0.0;
  double max_regret = 0.0;
  void Validate() const;
};

using CheckKind = std::variant<FreeRollCheck, NoTunnellingCheck, ReboundCheck, RobotReboundCheck,
                               KickDirectionCheck, CalibrationBandCheck, FidelityFloorCheck>;

std::string_view KindName(const CheckKind& kind);

// One check as the spec file gives it, validated.
struct CheckSpec {
  std::string name;
  CheckKind kind;
  std::string where;          // "FILE: checks[i]" for messages
  std::filesystem::path dir;  // the spec file's folder (file references are relative to it)
  std::optional<RobotBase> base;  // `check --base`: the kicking robot's base in every check
};

// Loads every file the check reads and checks every name it gives, without running it;
// InputError on files that do not load.
void PrepareCheck(const CheckSpec& spec, const std::filesystem::path& models_dir);

// Runs one check (threads: for the physics trials); InputError on files that do not load.
CheckResult RunCheck(const CheckSpec& spec, const std::filesystem::path& models_dir, int threads);

}  // namespace foresight
