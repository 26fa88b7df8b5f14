#include "app/cli_main.h"

#include <cstdio>
#include <iostream>
#include <new>

#include "common/error.h"
#include "models/model_paths.h"

namespace foresight {
namespace {

constexpr std::size_t kMaxMessageBytes = 2000;

}  // namespace

void AddTopLevelOptions(CLI::App& app, std::string& models_dir) {
  app.description("foresight: robot-soccer kick selection by forward simulation");
  app.set_version_flag("--version", FORESIGHT_VERSION);
  app.require_subcommand(1);
  app.add_option("--models", models_dir,
                 "Folder of the shipped data (default: " + DefaultModelsDir().string() + ")");
}

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
    return FailBadInput(e.what());
  }
  return std::nullopt;
}

int RunReportingErrors(const std::function<int()>& command) {
  try {
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
