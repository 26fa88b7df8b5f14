// `foresight fidelity`: how well the coarse model ranks and chooses kicks against physics, on a
// set of situations; writes JSON, CSV and an HTML report to a folder.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "app/cli_values.h"
#include "validation/fidelity.h"

namespace foresight {

// The defaults are FidelitySettings' (shown by --help).
struct FidelityOptions {
  std::string situations = "default";  // a set file, or a name in MODELS/fidelity/
  std::string trials = std::to_string(FidelitySettings{}.physics_trials);  // per candidate
  // Coarse samples (0: the evaluation file's N).
  std::string samples = std::to_string(FidelitySettings{}.coarse_samples);
  // Samples of the converged coarse model.
  std::string converged = std::to_string(FidelitySettings{}.converged_samples);
  std::string seed = std::to_string(FidelitySettings{}.seed);
  std::string threads = std::to_string(FidelitySettings{}.threads);
  std::string kicks_file;
  std::string physics_file;
  std::string out_dir;
};

void AddFidelityCommand(CLI::App& app, FidelityOptions& options);
int RunFidelityCommand(const FidelityOptions& options, const std::string& models_dir);

}  // namespace foresight
