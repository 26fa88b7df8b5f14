// The `foresight` command line: one binary, one subcommand per job. Bad input of any kind ends
// in one line "foresight: error: ..." on stderr and exit code 2 (docs/ARCHITECTURE.md, "Errors").
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <new>
#include <string>

#include "app/calibrate_command.h"
#include "app/cbr_command.h"
#include "app/check_command.h"
#include "app/decide_command.h"
#include "app/experiment_command.h"
#include "app/fidelity_command.h"
#include "app/merge_command.h"
#include "app/simulate_command.h"
#include "common/error.h"
#include "common/one_line.h"
#include "models/model_paths.h"

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 3;

int Fail(const std::string& message) {
  std::cerr << "foresight: error: " << foresight::OneLine(message) << "\n";
  return kExitBadInput;
}

// An empty value is refused, never read as "flag not given" (`--svg ''` would draw nothing,
// `check --spec ''` run the default spec for minutes).
void RefuseEmptyValues(const CLI::App& app) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0 || option->get_expected_min() == 0) continue;  // a flag
    for (const std::string& value : option->results()) {
      if (value.empty()) {
        throw foresight::InputError(option->get_name() + ": empty value (leave the flag out for "
                                    "its default)");
      }
    }
  }
  for (const CLI::App* sub : app.get_subcommands()) RefuseEmptyValues(*sub);
}

// CLI11 words a mistyped command "A subcommand is required"; the user gets the word instead.
std::string UnknownCommand(const CLI::App& app, int argc, char** argv) {
  std::string names;
  for (const CLI::App* sub : app.get_subcommands({})) {
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--models") {
      ++i;
      continue;
    }
    if (word.empty() || word[0] == '-') continue;
    return "unknown command '" + word + "' (one of: " + names + ")";
  }
  return "a command is required (one of: " + names + ")";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"foresight: robot-soccer kick selection by forward simulation"};
  app.set_version_flag("--version", FORESIGHT_VERSION);
  app.require_subcommand(1);
  std::string models_dir;
  app.add_option("--models", models_dir,
                 "Folder of the shipped data (default: " + foresight::DefaultModelsDir().string() +
                     ")");
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

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (app.get_subcommands().empty()) return Fail(UnknownCommand(app, argc, argv));
    return Fail(e.what());
  }

  try {
    RefuseEmptyValues(app);
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
  } catch (const foresight::InputError& e) {
    return Fail(e.what());
  } catch (const std::bad_alloc&) {
    // Not a bug but the machine's or the job's limit (`ulimit -v`, a Slurm job's memory).
    return Fail("out of memory (a memory limit such as ulimit -v? a smaller run may fit)");
  } catch (const std::exception& e) {
    std::cerr << "foresight: internal error: " << foresight::OneLine(e.what()) << "\n";
    return kExitInternal;
  }
  return kExitBadInput;
}
