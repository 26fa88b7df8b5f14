// Files for tests at every layer (header-only, so common_tests and stats_tests need no library
// above theirs): the shipped data folder and per-test temporary files.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace foresight::testing {

// The shipped models/ folder (FORESIGHT_TEST_MODELS_DIR is set by tests/CMakeLists.txt).
inline std::filesystem::path ModelsDir() {
  return FORESIGHT_TEST_MODELS_DIR;
}

// Writes `text` to a fresh file in a per-test temporary folder and returns its path. The folder
// is per process: ctest runs every test in its own process, in parallel and possibly from other
// checkouts at the same time, and two tests writing "case.json" to one folder race.
inline std::filesystem::path WriteTempFile(const std::string& name, const std::string& text) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "foresight_tests" /
                                    ("pid" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / name;
  std::ofstream(file) << text;
  return file;
}

// A new, empty folder `name` in this process's temporary folder.
inline std::filesystem::path FreshTempDir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "foresight_tests" /
                                    ("pid" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The names of the entries of `dir` (files and folders, not recursive).
inline std::set<std::string> FolderNames(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

// The whole text of `file` ("" if it cannot be read).
inline std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace foresight::testing
