// The `foresight` command line: one binary, one subcommand per job. Bad input of any kind ends
// in one line "foresight: error: ..." on stderr and exit code 2 (docs/ARCHITECTURE.md, "Errors").
#include <CLI/CLI.hpp>
#include <string>

#include "app/calibrate_command.h"
#include "app/cbr_command.h"
#include "app/check_command.h"
#include "app/cli_main.h"
#include "app/decide_command.h"
#include "app/experiment_command.h"
#include "app/fidelity_command.h"
#include "app/merge_command.h"
#include "app/simulate_command.h"

int main(int argc, char** argv) {
  CLI::App app;
  std::string models_dir;
  foresight::AddTopLevelOptions(app, models_dir);
  foresight::DecideOptions decide;
  foresight::AddDecideCommand(app, decide);
  foresight::SimulateOptions simulate;
  foresight::AddSimulateCommand(app, simulate);
  foresight::CalibrateOptions calibrate;
  foresight::AddCalibrateCommand(app, calibrate);
  foresight::CheckOptions check;
  foresight::AddCheckCommand(app, check);
  foresight::FidelityOptions fidelity;
  foresight::AddFidelityCommand(app, fidelity);
  foresight::ExperimentOptions experiment;
  foresight::AddExperimentCommand(app, experiment);
  foresight::CbrOptions cbr;
  foresight::AddCbrCommand(app, cbr);
  foresight::MergeOptions merge;
  foresight::AddMergeCommand(app, merge);

  if (const auto parsed = foresight::ParseCommandLine(app, argc, argv)) return *parsed;
  return foresight::RunReportingErrors([&] {
    if (app.got_subcommand("decide")) return foresight::RunDecide(decide, models_dir);
    if (app.got_subcommand("simulate")) return foresight::RunSimulate(simulate, models_dir);
    if (app.got_subcommand("calibrate")) return foresight::RunCalibrate(calibrate, models_dir);
    if (app.got_subcommand("check")) return foresight::RunCheckCommand(check, models_dir);
    if (app.got_subcommand("experiment")) {
      return foresight::RunExperimentCommand(app, experiment, models_dir);
    }
    if (app.got_subcommand("cbr")) return foresight::RunCbrCommand(cbr, models_dir);
    if (app.got_subcommand("fidelity")) {
      return foresight::RunFidelityCommand(fidelity, models_dir);
    }
    if (app.got_subcommand("merge")) return foresight::RunMergeCommand(merge, models_dir);
    return foresight::kExitBadInput;
  });
}
