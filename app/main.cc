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
#include "models/model_paths.h"

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 3;

constexpr std::size_t kMaxMessageBytes = 2000;

// The promise is one line: control characters (a name with a newline in it) are escaped, and a
// message is cut after kMaxMessageBytes.
std::string OneLine(const std::string& message) {
  std::string line;
  for (const char c : message.substr(0, kMaxMessageBytes)) {
    if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) {
      line += c;
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned char>(c));
      line += c == '\n' ? std::string("\\n") : std::string(escaped);
    }
  }
  if (message.size() > kMaxMessageBytes)
    line += "... (" + std::to_string(message.size()) + " bytes)";
  return line;
}

int Fail(const std::string& message) {
  std::cerr << "foresight: error: " << OneLine(message) << "\n";
  return kExitBadInput;
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
    return Fail(e.what());
  }

  try {
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
    std::cerr << "foresight: internal error: " << OneLine(e.what()) << "\n";
    return kExitInternal;
  }
  return kExitBadInput;
}
