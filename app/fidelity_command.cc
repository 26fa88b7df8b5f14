#include "app/fidelity_command.h"

#include <chrono>
#include <iostream>

#include "app/cli_values.h"
#include "app/report_text.h"
#include "common/error.h"
#include "models/model_paths.h"
#include "report/atomic_file.h"
#include "validation/fidelity_html.h"
#include "validation/fidelity_report.h"

namespace foresight {

void AddFidelityCommand(CLI::App& app, FidelityOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "fidelity", "Compare the coarse model's rankings and decisions with physics");
  cmd->add_option("--situations", options.situations,
                  "Situation set: a file, or a name in MODELS/fidelity/ (default, quick)")
      ->capture_default_str();
  cmd->add_option("--trials", options.trials, "Physics trials per candidate")
      ->capture_default_str();
  cmd->add_option("--samples", options.samples, "Coarse samples N (0: the evaluation file's)")
      ->capture_default_str();
  cmd->add_option("--converged", options.converged, "Samples of the converged coarse model")
      ->capture_default_str();
  cmd->add_option("--seed", options.seed, "Random seed")->capture_default_str();
  cmd->add_option("--threads", options.threads, "Worker threads (0: all cores)")
      ->capture_default_str();
  cmd->add_option("--kicks", options.kicks_file, "Kick model replacing every situation's");
  cmd->add_option("--physics", options.physics_file,
                  "Physics file (default: MODELS/physics/<field>.json)");
  cmd->add_option("--out", options.out_dir, "Folder for the report")->required();
}

int RunFidelityCommand(const FidelityOptions& options, const std::string& models_dir) {
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path models =
      models_dir.empty() ? DefaultModelsDir() : std::filesystem::path(models_dir);
  FidelityRun run;
  run.provenance.version = FORESIGHT_VERSION;
  run.settings.physics_trials = ParseCount("--trials", options.trials, 2, 100000);
  run.settings.coarse_samples = ParseCount("--samples", options.samples, 0, 1000000);
  run.settings.converged_samples = ParseCount("--converged", options.converged, 1, 10000000);
  run.settings.seed = run.provenance.seed = ParseSeed(options.seed);
  run.settings.threads = ParseCount("--threads", options.threads, 0, 1024);
  run.settings.physics_file = options.physics_file;
  run.settings.progress = TerminalProgress("fidelity:", "situations");
  CheckReportDir(options.out_dir, "--out");  // before the work, not after
  const FidelitySet set = LoadFidelitySet(options.situations, models, options.kicks_file);
  run.provenance.inputs = {{"situations_set", set.name},
                           {"set_file", DisplayPath(set.file, models)},
                           {"physics_file", options.physics_file.empty() ? "physics/<field>.json"
                                                                         : options.physics_file}};
  run.rotations_rad = set.rotations_rad;
  run.result = RunFidelity(set, models, run.settings);
  run.provenance.run_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::filesystem::path dir(options.out_dir);
  const ReportFiles files = {{dir / "fidelity.json", FidelityJson(run).dump(2) + "\n"},
                             {dir / "fidelity_candidates.csv", FidelityCandidatesCsv(run)},
                             {dir / "fidelity_situations.csv", FidelitySituationsCsv(run)},
                             {dir / "fidelity.html", FidelityHtml(run)}};
  const std::string text = FidelityText(run);
  WriteReportFiles(options.out_dir, "--out", files);
  std::cout << text << "report: " << (dir / "fidelity.html").string() << "\n" << std::flush;
  if (!std::cout) throw InputError("cannot write to standard output");
  return 0;
}

}  // namespace foresight
