// What the experiment commands (app/stability_command.h, app/strategies_command.h,
// app/passing_command.h, app/ablations_command.h) share: the models folder, the run time, the
// provenance of a run and the writing of its report folder with the terminal text.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>

#include "app/cli_values.h"
#include "models/situation.h"
#include "report/provenance.h"

namespace foresight {

// --models as given, or the shipped data next to the binary.
std::filesystem::path ModelsFolder(const std::string& models_dir);

double SecondsSince(std::chrono::steady_clock::time_point start);

// An experiment's version, seed and inputs: its params file, its scene's name and kick model.
RunProvenance ExperimentProvenance(const std::filesystem::path& params_file, const Situation& scene,
                                   std::uint64_t seed, const std::filesystem::path& models);

// Commits `files` as the report folder --out that `outputs` declared before the work (every
// file computed before the first is written, the folder replaced whole) and prints `text` and
// where the figures are (`main_file`).
void WriteReport(OutputSet& outputs, const std::string& out_dir, const ReportFiles& files,
                 const std::string& text, const std::string& main_file);

}  // namespace foresight
