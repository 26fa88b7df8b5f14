// `foresight fidelity`: how well the coarse model ranks and chooses kicks against physics, on a
// set of situations; writes JSON, CSV and an HTML report to a folder.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli_values.h"
#include "report/output_set.h"
#include "report/shard_file.h"
#include "validation/fidelity.h"
#include "validation/fidelity_report.h"

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
  std::string base;             // --base: empty, the physics files'
  std::string situation_class;  // empty: every class of the set
  std::string coarse_rebounds;  // "on", "off" or empty (the evaluation files')
  std::string out_dir;
  std::string shard;  // "I/N": only that shard (app/shard_output.h); empty: the whole run
};

void AddFidelityCommand(CLI::App& app, FidelityOptions& options);
int RunFidelityCommand(const FidelityOptions& options, const std::string& models_dir);

// The whole run without writing anything (the Python module's fidelity); options.out_dir empty.
FidelityRun RunFidelityInMemory(const FidelityOptions& options,
                                const std::filesystem::path& models);

// `foresight merge` of a sharded fidelity run into the report folder `out_dir`.
inline constexpr char kFidelityCommand[] = "fidelity";
int MergeFidelityCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                         const std::string& out_dir, const std::filesystem::path& models);

}  // namespace foresight
