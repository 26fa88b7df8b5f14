#include "models/model_paths.h"

#include <dlfcn.h>

#include <cstdlib>
#include <system_error>

#include "common/enum_names.h"
#include "common/error.h"

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

std::string DisplayPath(const std::filesystem::path& file,
                        const std::filesystem::path& models_dir) {
  const std::filesystem::path relative =
      std::filesystem::absolute(file).lexically_normal().lexically_relative(
          std::filesystem::absolute(models_dir).lexically_normal());
  if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
  return file.generic_string();
}

std::filesystem::path DefaultModelsDir() {
  if (const char* env = std::getenv("FORESIGHT_MODELS_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  // An installed binary (PREFIX/bin) finds PREFIX/share/foresight/models, wherever the tree was
  // moved; so does the installed Python module (PREFIX/lib/python3/dist-packages), whose
  // process is python3. A binary in the build tree has no such folder beside it.
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path beside = exe.parent_path() / FORESIGHT_MODELS_FROM_BIN;
    if (std::filesystem::is_directory(beside, error)) return beside.lexically_normal();
  }
  // The Python module (the package folder foresight/ holding the code): its own models/ when
  // pip installed it from a wheel, PREFIX/share/foresight/models when cmake --install or the
  // .deb did.
  Dl_info self{};
  if (dladdr(reinterpret_cast<void*>(&DefaultModelsDir), &self) != 0 && self.dli_fname != nullptr) {
    const std::filesystem::path package = std::filesystem::path(self.dli_fname).parent_path();
    for (const std::filesystem::path& beside :
         {package / "models", package / FORESIGHT_MODELS_FROM_PYTHON}) {
      if (std::filesystem::is_directory(beside, error)) return beside.lexically_normal();
    }
  }
  // Compile definitions: the source tree's models/, then the install prefix's data folder (a
  // program linked against an installed foresight lives elsewhere than PREFIX/bin).
  if (std::filesystem::is_directory(FORESIGHT_MODELS_DIR, error)) return FORESIGHT_MODELS_DIR;
  return FORESIGHT_INSTALLED_MODELS_DIR;
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

std::filesystem::path NamedFile(std::string_view key, const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(file, ec)) return file;
  const bool exists = std::filesystem::exists(file, ec);
  throw InputError(std::string(key) + ": refers to " + file.string() +
                   (exists ? ", which is not a regular file (a device or a pipe?)"
                           : ", which does not exist"));
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
