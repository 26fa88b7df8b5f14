#include "app/experiment_output.h"

#include <iostream>

#include "common/error.h"
#include "common/one_line.h"
#include "models/model_paths.h"

namespace foresight {

std::filesystem::path ModelsFolder(const std::string& models_dir) {
  return models_dir.empty() ? DefaultModelsDir() : std::filesystem::path(models_dir);
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

RunProvenance ExperimentProvenance(const std::filesystem::path& params_file, const Situation& scene,
                                   std::uint64_t seed, const std::filesystem::path& models) {
  RunProvenance provenance;
  provenance.version = FORESIGHT_VERSION;
  provenance.seed = seed;
  provenance.inputs = {{"file", DisplayPath(params_file, models)},
                       {"situation", scene.name},
                       {"kicks", DisplayPath(scene.kicks_file, models)},
                       {"kicks_hash", ContentHash(scene.kicks_file)}};
  return provenance;
}

void WriteReport(OutputSet& outputs, const std::string& out_dir, const ReportFiles& files,
                 const std::string& text, const std::string& main_file) {
  outputs.Put("--out", ReportFolderFiles(files));
  outputs.Commit();
  std::cout << PrintableLines(text)
            << "figures and data: " << (std::filesystem::path(out_dir) / main_file).string()
            << " and the other files in " << out_dir << "\n"
            << std::flush;
  if (!std::cout) throw InputError("cannot write to standard output");
}

}  // namespace foresight
