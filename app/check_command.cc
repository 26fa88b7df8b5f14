#include "app/check_command.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "app/base_flag.h"
#include "app/cli_values.h"
#include "common/error.h"
#include "common/one_line.h"
#include "models/model_paths.h"
#include "report/output_set.h"
#include "report/provenance.h"
#include "validation/physics_checks.h"

namespace foresight {

namespace {

// The physics files a check may read: every check reads its field's MODELS/physics/<field>.json.
std::vector<std::filesystem::path> CheckPhysicsFiles(const std::filesystem::path& models) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(DataFolderPath(models, DataFolder::kPhysics))) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

void AddCheckCommand(CLI::App& app, CheckOptions& options) {
  CLI::App* cmd = app.add_subcommand("check", "Run physics expectations from a spec file (CI)");
  cmd->add_option("--spec", options.spec_file,
                  "Spec file (default: MODELS/check_specs/default.json)");
  cmd->add_option("--junit", options.junit_file, "Write the results as JUnit XML");
  cmd->add_option("--threads", options.threads, "Worker threads (0: all cores)")
      ->capture_default_str();
  AddBaseOption(*cmd, options.base);
}

int RunCheckCommand(const CheckOptions& options, const std::string& models_dir) {
  const std::filesystem::path models =
      models_dir.empty() ? DefaultModelsDir() : std::filesystem::path(models_dir);
  const int threads = ParseCount("--threads", options.threads, 0, 1024);
  OutputSet outputs;  // located and checked before the checks run
  outputs.AddInput("the input --spec", options.spec_file);
  outputs.AddFile("--junit", options.junit_file);
  const std::filesystem::path spec_file = options.spec_file.empty()
                                              ? DataFile(models, DataFolder::kCheckSpecs, "default")
                                              : std::filesystem::path(options.spec_file);
  const std::optional<RobotBase> base = ParseBaseFlag(options.base);
  CheckSuite suite = LoadCheckSuite(spec_file);
  for (CheckSpec& check : suite.checks) check.base = base;
  int failed = 0;
  const std::vector<CheckResult> results =
      RunChecks(suite, models, threads, [&](const CheckResult& r) {
        failed += !r.passed;
        std::ostringstream line;
        line << (r.passed ? "PASS " : "FAIL ") << r.name << " (" << r.kind << ", "
             << static_cast<int>(r.time_s * 10.0 + 0.5) / 10.0 << " s): " << r.detail;
        std::cout << PrintableName(line.str()) << "\n" << std::flush;
      });
  if (outputs.Has("--junit")) {
    outputs.Put("--junit", JUnitXml("foresight check " + suite.name, results,
                                    {{"version", FORESIGHT_VERSION},
                                     {"spec", DisplayPath(spec_file, models)},
                                     {"spec_hash", ContentHash(spec_file)},
                                     {"robot_base", BaseUsed(base, CheckPhysicsFiles(models))}}));
  }
  outputs.Commit();
  std::cout << results.size() - failed << " of " << results.size() << " checks passed\n"
            << std::flush;
  if (!std::cout) throw InputError("cannot write to standard output");
  return failed == 0 ? 0 : 1;
}

}  // namespace foresight
