// `foresight fidelity`: how well the coarse model ranks and chooses kicks against physics, on a
// set of situations; writes JSON, CSV and an HTML report to a folder.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace foresight {

struct FidelityOptions {
  std::string situations = "default";  // a set file, or a name in MODELS/fidelity/
  std::string trials = "30";           // physics trials per candidate
  std::string samples = "0";           // coarse samples (0: the evaluation file's N)
  std::string converged = "2000";      // samples of the converged coarse model
  std::string seed = "1";
  std::string threads = "0";
  std::string kicks_file;
  std::string physics_file;
  std::string out_dir;
};

void AddFidelityCommand(CLI::App& app, FidelityOptions& options);
int RunFidelityCommand(const FidelityOptions& options, const std::string& models_dir);

}  // namespace foresight
