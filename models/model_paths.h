// Where the shipped data lives and how files name each other.
//
// A situation names its field, kick model and evaluation either by a bare name ("spl"), found
// as MODELS_DIR/fields/spl.json, or by a path ending in ".json", taken relative to the file
// that names it. MODELS_DIR is, in this order: the --models flag, the environment variable
// FORESIGHT_MODELS_DIR, or the source tree's models/ folder compiled into the binary.
#pragma once

#include <filesystem>
#include <string>

namespace foresight {

std::filesystem::path DefaultModelsDir();

// Resolves `reference` from a file in `referring_dir`; `kind` is the sub-folder ("fields").
std::filesystem::path ResolveModelFile(const std::string& reference, const std::string& kind,
                                       const std::filesystem::path& referring_dir,
                                       const std::filesystem::path& models_dir);

}  // namespace foresight
