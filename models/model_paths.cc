#include "models/model_paths.h"

#include <cstdlib>

#include "common/enum_names.h"

namespace foresight {
namespace {

constexpr EnumNames<DataFolder, 14> kFolderNames{{{
    {DataFolder::kFields, "fields"},
    {DataFolder::kKicks, "kicks"},
    {DataFolder::kEvaluation, "evaluation"},
    {DataFolder::kSituations, "situations"},
    {DataFolder::kPhysics, "physics"},
    {DataFolder::kRobots, "robots"},
    {DataFolder::kCalibration, "calibration"},
    {DataFolder::kFidelity, "fidelity"},
    {DataFolder::kCheckSpecs, "check_specs"},
    {DataFolder::kExperiments, "experiments"},
    {DataFolder::kCases, "cases"},
    {DataFolder::kMatch, "match"},
    {DataFolder::kMatchScenarios, "match/scenarios"},
    {DataFolder::kCbr, "cbr"},
}}};

}  // namespace

std::filesystem::path DefaultModelsDir() {
  if (const char* env = std::getenv("FORESIGHT_MODELS_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  return FORESIGHT_MODELS_DIR;  // compile definition: the source tree's models/
}

std::string_view DataFolderName(DataFolder folder) {
  return kFolderNames.Name(folder);
}

std::filesystem::path DataFolderPath(const std::filesystem::path& models_dir, DataFolder folder) {
  return models_dir / DataFolderName(folder);
}

std::filesystem::path DataFile(const std::filesystem::path& models_dir, DataFolder folder,
                               const std::string& name) {
  return DataFolderPath(models_dir, folder) / (name + ".json");
}

std::filesystem::path ResolveModelFile(const std::string& reference, DataFolder folder,
                                       const std::filesystem::path& referring_dir,
                                       const std::filesystem::path& models_dir) {
  const bool is_path = reference.size() > 5 && reference.ends_with(".json");
  if (!is_path) return DataFile(models_dir, folder, reference);
  std::filesystem::path path(reference);
  return path.is_absolute() ? path : referring_dir / path;
}

}  // namespace foresight
