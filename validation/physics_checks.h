// `foresight check`: physics expectations from a data file (models/check_specs/*.json), each
// a pass or a fail with a one-line reason, for CI.
//
// A spec file: {"name": ..., "checks": [{"name": ..., "kind": ..., KEYS}, ...]} with the check
// names unique. Kinds of check and their keys (validation/check_kinds.h has what each tests):
//   free_roll         field, speed_mps, heading_deg, max_error_rel, max_lateral_m
//   no_tunnelling     field, target (post | back_net | side_net), speed_mps, phases,
//                     max_penetration_steps
//   rebound           field, target, speeds_mps, phases, max_error_rel, min_error_mps
//   kick_direction    robot, kick, kicks (model), trials, max_error_deg
//   calibration_band  robot, kicks, trials, seed, band_rel, band_deg
//   fidelity_floor    situations, kicks, trials, min_tau_b, max_regret
// A check may also have "notes"; any other key is an error.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "validation/check_kinds.h"

namespace foresight {

struct CheckSuite {
  std::string name;
  std::filesystem::path file;
  std::vector<CheckSpec> checks;
};

// Reads and validates the whole spec before anything runs; InputError on bad input.
CheckSuite LoadCheckSuite(const std::filesystem::path& file);

// Runs every check in order (threads: for the physics trials). `on_result` sees each result as
// soon as it is known.
std::vector<CheckResult> RunChecks(const CheckSuite& suite, const std::filesystem::path& models_dir,
                                   int threads,
                                   const std::function<void(const CheckResult&)>& on_result);

// JUnit XML (the Ant/Jenkins schema most CI systems read): one testsuite, one testcase per check.
// `properties` (name, value) go into the testsuite's <properties>: what the run used (version,
// spec file and its content hash). Every name and text is written in its printable form
// (common/one_line.h), so the file is well-formed XML whatever a spec's names hold.
std::string JUnitXml(const std::string& suite_name, const std::vector<CheckResult>& results,
                     const std::vector<std::pair<std::string, std::string>>& properties = {});

}  // namespace foresight
