#include "models/model_paths.h"

#include <cstdlib>

namespace foresight {

std::filesystem::path DefaultModelsDir() {
  if (const char* env = std::getenv("FORESIGHT_MODELS_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  return FORESIGHT_MODELS_DIR;  // compile definition: the source tree's models/
}

std::filesystem::path ResolveModelFile(const std::string& reference, const std::string& kind,
                                       const std::filesystem::path& referring_dir,
                                       const std::filesystem::path& models_dir) {
  const bool is_path = reference.size() > 5 && reference.ends_with(".json");
  if (!is_path) return models_dir / kind / (reference + ".json");
  std::filesystem::path path(reference);
  return path.is_absolute() ? path : referring_dir / path;
}

}  // namespace foresight
