// What the two executables of the command line share (app/main.cc, every command; app/
// front_main.cc, the quick `decide`): the top-level options and the error policy
// (docs/ARCHITECTURE.md, "Errors"): bad input of any kind ends in one line "foresight: error: ..."
// on stderr and exit code 2; a bug ends in "foresight: internal error: ..." and exit code 3.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace foresight {

inline constexpr int kExitBadInput = 2;
inline constexpr int kExitInternal = 3;

// The `foresight` app with its description, --version and --models (into models_dir).
void AddTopLevelOptions(CLI::App& app, std::string& models_dir);

// The command named on the command line: the first argument that is not a top-level option
// (only --models takes a value); empty when there is none (`foresight --help`).
std::string_view FirstCommandWord(int argc, char** argv);

// Prints "foresight: error: MESSAGE" as one line; returns kExitBadInput.
int FailBadInput(const std::string& message);

// Parses the command line; returns the exit code when parsing ends the run (help, version, a
// parse error, an unknown command named as such, an empty value: never read as "flag not
// given"), nullopt when the command is to run.
std::optional<int> ParseCommandLine(CLI::App& app, int argc, char** argv);

// Runs a command, mapping what it throws to the policy's line and exit code.
int RunReportingErrors(const std::function<int()>& command);

}  // namespace foresight
