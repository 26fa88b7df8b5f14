// Where the shipped data lives and how files name each other.
//
// A situation names its field, kick model and evaluation either by a bare name ("spl"), found
// as MODELS_DIR/fields/spl.json, or by a path ending in ".json", taken relative to the file
// that names it. MODELS_DIR is, in this order: the --models flag, the environment variable
// FORESIGHT_MODELS_DIR, the installed data beside the running binary (BIN/../share/foresight/
// models, so an installed tree can be moved) or beside the installed Python module that holds
// this code (its package's models/ from a pip-installed wheel, or the prefix's share/foresight/
// models), the source tree's models/ folder compiled into the
// library, or the install prefix's data folder compiled into it (for programs linked against an
// installed foresight that live outside its bin/).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace foresight {

std::filesystem::path DefaultModelsDir();

// A data file as reports show it: relative to the models folder when inside it, so the same
// run gives the same bytes in every checkout.
std::string DisplayPath(const std::filesystem::path& file, const std::filesystem::path& models_dir);

// The folders of MODELS_DIR, by what they hold; the one place their names are spelled.
enum class DataFolder {
  kFields,
  kKicks,
  kEvaluation,
  kSituations,
  kPhysics,
  kRobots,
  kCalibration,
  kFidelity,
  kCheckSpecs,
  kExperiments,
  kCases,
  kMatch,           // the match simulator: robot, simulation, configurations, teams
  kMatchScenarios,  // the match scenarios (Ros et al. 2009, Fig. 12)
  kCbr,             // case retrieval and the CBR team's parameters
};
std::string_view DataFolderName(DataFolder folder);  // "fields", "kicks", ...

// MODELS_DIR/<folder>, and the shipped file MODELS_DIR/<folder>/<name>.json.
std::filesystem::path DataFolderPath(const std::filesystem::path& models_dir, DataFolder folder);
std::filesystem::path DataFile(const std::filesystem::path& models_dir, DataFolder folder,
                               const std::string& name);

// Resolves `reference` (a bare name in `folder`, or a path ending in ".json") from a file in
// `referring_dir`.
std::filesystem::path ResolveModelFile(const std::string& reference, DataFolder folder,
                                       const std::filesystem::path& referring_dir,
                                       const std::filesystem::path& models_dir);

// `file`, named by the field `key` of a data file; an InputError against that field when it is no
// regular file ("kicks: refers to F, which does not exist", or "..., which is not a regular
// file" for a device or a pipe), for the caller to prefix with the naming file as it prefixes
// its other errors.
std::filesystem::path NamedFile(std::string_view key, const std::filesystem::path& file);

}  // namespace foresight
