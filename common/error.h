// The project's error type for bad input from a user (a file, a flag, a value).
//
// docs/ARCHITECTURE.md, "Errors": a programmer's bug is an assertion; bad user input is an
// InputError whose message names the file, the field and the value (the CLI prints it as one line
// and exits 2); an expected outcome (ball out, nothing acceptable) is a value, never an exception.
#pragma once

#include <stdexcept>
#include <string>

namespace foresight {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// Runs `check` (a Validate() or a check from common/checks.h, whose messages say "field: ...")
// and prefixes `file` to the message of any InputError it throws: "FILE: field: ...".
template <typename Check>
void WithFile(const std::string& file, Check&& check) {
  try {
    check();
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }
}

}  // namespace foresight
