// `foresight check`: physics expectations from a data file (models/check_specs/*.json), each
// a pass or a fail with a one-line reason, for CI.
//
// Kinds of check (all numbers come from the spec file):
//   free_roll       a ball set rolling on a uniform carpet (the field's physics file, its
//                   variation switched off) stops at v^2 / 2a within max_error_rel and within
//                   max_lateral_m of its line. Keys: field, speed_mps, heading_deg,
//                   max_error_rel, max_lateral_m.
//   no_tunnelling   a fast ball fired at a post, the back net or a side net from outside never
//                   gets closer to it than the ball's radius less max_penetration_m. Keys:
//                   field, target (post | back_net | side_net), speed_mps, max_penetration_m.
//   kick_direction  a robot's kick, trials times from its calibration situation: every trial
//                   touches the ball and the circular mean direction lies within max_error_deg
//                   of the kick model's. Keys: robot, kick, kicks (model), trials,
//                   max_error_deg.
//   calibration_band  calibrating every kick of a robot from trials physics kicks (seeded as
//                   `calibrate --seed` seeds them) gives v0, sigma_v and sigma_alpha within
//                   band_rel (relative) and alpha within band_deg of the committed kick model.
//                   With the calibration's own seed and trials it is a drift guard (the numbers
//                   are reproduced exactly unless physics changed); with another seed it also
//                   tests the sampling error. Keys: robot, kicks, trials, seed, band_rel,
//                   band_deg.
//   fidelity_floor  a fidelity run on a situation set: the mean Kendall tau-b of the coarse
//                   model is at least min_tau_b and its mean regret at most max_regret. Keys:
//                   situations, kicks, trials, min_tau_b, max_regret.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace foresight {

struct CheckResult {
  std::string name;
  std::string kind;
  bool passed = false;
  std::string detail;  // one line: what was measured against what was expected
  double time_s = 0.0;
};

// One check as the spec file gives it, its keys already checked for its kind.
struct CheckSpec {
  std::string name;
  std::string kind;
  std::map<std::string, std::string> text;
  std::map<std::string, double> number;
  std::string where;          // "FILE: checks[i]" for messages
  std::filesystem::path dir;  // the spec file's folder (file references are relative to it)
};

struct CheckSuite {
  std::string name;
  std::filesystem::path file;
  std::vector<CheckSpec> checks;
};

// Runs one check (check_kinds.cc).
CheckResult RunCheck(const CheckSpec& spec, const std::filesystem::path& models_dir, int threads);

// Reads and validates the whole spec before anything runs; InputError on bad input.
CheckSuite LoadCheckSuite(const std::filesystem::path& file);

// Runs every check in order (threads: for the physics trials). `on_result` sees each result as
// soon as it is known.
std::vector<CheckResult> RunChecks(const CheckSuite& suite, const std::filesystem::path& models_dir,
                                   int threads,
                                   const std::function<void(const CheckResult&)>& on_result);

// JUnit XML (the Ant/Jenkins schema most CI systems read): one testsuite, one testcase per check.
std::string JUnitXml(const std::string& suite_name, const std::vector<CheckResult>& results);

}  // namespace foresight
