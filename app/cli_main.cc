#include "app/cli_main.h"

#include <iostream>
#include <new>

#include "common/error.h"
#include "common/input_log.h"
#include "common/one_line.h"
#include "models/model_paths.h"

namespace foresight {
namespace {

// An empty value is refused, never read as "flag not given" (`--svg ''` would draw nothing,
// `check --spec ''` run the default spec for minutes).
void RefuseEmptyValues(const CLI::App& app) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0 || option->get_expected_min() == 0) continue;  // a flag
    for (const std::string& value : option->results()) {
      if (value.empty()) {
        throw InputError(option->get_name() + ": empty value (leave the flag out for its default)");
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
  const std::string_view word = FirstCommandWord(argc, argv);
  if (word.empty()) return "a command is required (one of: " + names + ")";
  return "unknown command '" + std::string(word) + "' (one of: " + names + ")";
}

}  // namespace

std::string_view FirstCommandWord(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word == "--models") {
      ++i;
    } else if (!word.empty() && word[0] != '-') {
      return word;
    }
  }
  return {};
}

void AddTopLevelOptions(CLI::App& app, std::string& models_dir) {
  app.description("foresight: robot-soccer kick selection by forward simulation");
  app.set_version_flag("--version", FORESIGHT_VERSION);
  app.require_subcommand(1);
  app.add_option("--models", models_dir,
                 "Folder of the shipped data (default: " + DefaultModelsDir().string() + ")");
}

int FailBadInput(const std::string& message) {
  std::cerr << "foresight: error: " << OneLine(message) << "\n";
  return kExitBadInput;
}

std::optional<int> ParseCommandLine(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (app.get_subcommands().empty()) return FailBadInput(UnknownCommand(app, argc, argv));
    return FailBadInput(e.what());
  }
  try {
    RefuseEmptyValues(app);
  } catch (const InputError& e) {
    return FailBadInput(e.what());
  }
  return std::nullopt;
}

int RunReportingErrors(const std::function<int()>& command) {
  try {
    const InputLog read;  // no output may replace a file the command read
    return command();
  } catch (const InputError& e) {
    return FailBadInput(e.what());
  } catch (const std::bad_alloc&) {
    // Not a bug but the machine's or the job's limit (`ulimit -v`, a Slurm job's memory).
    return FailBadInput("out of memory (a memory limit such as ulimit -v? a smaller run may fit)");
  } catch (const std::exception& e) {
    std::cerr << "foresight: internal error: " << OneLine(e.what()) << "\n";
    return kExitInternal;
  }
}

}  // namespace foresight
