// Helpers for the loader tests: read a shipped data file, break one thing in it, and catch the
// InputError its loader throws.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight::testing {

// The text of a shipped file, e.g. ShippedText("fields/spl.json").
inline std::string ShippedText(const std::string& relative) {
  std::ifstream in(ModelsDir() / relative);
  EXPECT_TRUE(in) << "cannot read shipped file " << relative;
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// `text` with the one occurrence of `from` replaced by `to`; fails the test if `from` does not
// occur exactly once (so a changed shipped file cannot silently disable a test).
inline std::string ReplaceOnce(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos || text.find(from, at + 1) != std::string::npos) {
    ADD_FAILURE() << "'" << from << "' does not occur exactly once in:\n" << text;
    return text;
  }
  return text.replace(at, from.size(), to);
}

// The shipped file `shipped` ("fields/spl.json") with `from` replaced by `to`, written to a
// temporary file called `temp_name`.json; returns its path.
inline std::filesystem::path BrokenShipped(const std::string& shipped, const std::string& temp_name,
                                           const std::string& from, const std::string& to) {
  return WriteTempFile(temp_name + ".json", ReplaceOnce(ShippedText(shipped), from, to));
}

// The message of the InputError `action` throws; a test failure if it throws nothing or
// something else.
template <typename Action>
std::string InputErrorMessage(Action&& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected an InputError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected an InputError, nothing was thrown";
  return "";
}

}  // namespace foresight::testing
