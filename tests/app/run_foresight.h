// Running the real `foresight` binary from tests: a fresh working folder per test, captured
// stdout, stderr and exit code, and small text helpers.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace foresight::testing {

namespace fs = std::filesystem;

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string ReadFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::string Quote(const std::string& arg) {
  std::string quoted = "'";
  for (char c : arg) quoted.append(c == '\'' ? "'\\''" : std::string(1, c));
  return quoted.append("'");
}

inline fs::path ShippedSituation(const std::string& name) {
  return fs::path(FORESIGHT_TEST_MODELS_DIR) / "situations" / (name + ".json");
}

inline std::string ShippedText(const std::string& name) {
  return ReadFile(ShippedSituation(name));
}

// `text` with its single occurrence of `from` replaced by `to`.
inline std::string ReplaceOnce(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos || text.find(from, at + 1) != std::string::npos) {
    ADD_FAILURE() << "'" << from << "' does not occur exactly once";
    return text;
  }
  return text.replace(at, from.size(), to);
}

// Every test gets a fresh working folder (the binary's current directory, where inputs and
// outputs go) and a separate folder for the captured streams.
class ForesightRun : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    std::replace(name.begin(), name.end(), '/', '_');
    root_ = fs::temp_directory_path() / "foresight_app_tests" /
            (name + "." + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(work());
    fs::create_directories(root_ / "capture");
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }

  fs::path work() const { return root_ / "work"; }

  fs::path Write(const std::string& name, const std::string& text) const {
    std::ofstream(work() / name) << text;
    return work() / name;
  }

  RunResult Run(const std::vector<std::string>& args) const {
    const fs::path out = root_ / "capture" / "stdout", err = root_ / "capture" / "stderr";
    std::string command = "cd ";
    command.append(Quote(work().string())).append(" && ").append(Quote(FORESIGHT_BINARY));
    for (const std::string& arg : args) command.append(" ").append(Quote(arg));
    command.append(" >").append(Quote(out.string()));
    command.append(" 2>").append(Quote(err.string())).append(" </dev/null");
    const int status = std::system(command.c_str());
    RunResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = ReadFile(out);
    result.err = ReadFile(err);
    return result;
  }

  RunResult Decide(std::vector<std::string> args) const {
    args.insert(args.begin(), "decide");
    return Run(args);
  }

  // All paths below the working folder, files and folders.
  std::set<std::string> Listing() const {
    std::set<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(work())) {
      names.insert(fs::relative(entry.path(), work()).string());
    }
    return names;
  }

  nlohmann::json DecideJson(std::vector<std::string> args) const {
    args.push_back("--json");
    const RunResult r = Decide(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    return nlohmann::json::parse(r.out);
  }

  fs::path root_;
};

// The files of two report folders compared as tests/shard/same_report.sh does: the same names
// and bytes, except the lines with the run time (JSON "run_time_s", an HTML page's "run time"
// row), which differ between two runs. Empty when they are the same, else what differs.
inline std::string ReportDifference(const fs::path& a, const fs::path& b) {
  const auto files = [](const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
      if (entry.is_regular_file()) names.insert(fs::relative(entry.path(), dir).string());
    }
    return names;
  };
  const auto without_run_time = [](const std::string& text) {
    std::istringstream in(text);
    std::string kept, line;
    while (std::getline(in, line)) {
      if (line.find("\"run_time_s\"") == std::string::npos &&
          line.find(">run time<") == std::string::npos)
        kept += line + "\n";
    }
    return kept;
  };
  if (files(a) != files(b)) return a.string() + " and " + b.string() + " hold different files";
  if (files(a).empty()) return a.string() + " is empty";
  for (const std::string& f : files(a)) {
    if (without_run_time(ReadFile(a / f)) != without_run_time(ReadFile(b / f))) return f + " differs";
  }
  return "";
}

inline int CountOf(const std::string& text, const std::string& part) {
  int count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
    ++count;
  }
  return count;
}

}  // namespace foresight::testing
