// `foresight check` against the real binary: its JUnit record names the base the checks used.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/app/run_foresight.h"

namespace {

namespace fs = std::filesystem;
using foresight::testing::ReadFile;
using foresight::testing::RunResult;
using ::testing::HasSubstr;

class CheckCommandTest : public foresight::testing::ForesightRun {
 protected:
  // One cheap check (a free roll): what is tested is the record, not the physics.
  fs::path OneCheckSpec() const {
    return Write("spec.json", R"({"name": "one", "checks": [
        {"name": "roll", "kind": "free_roll", "field": "spl", "speed_mps": 1.0,
         "heading_deg": 0.0, "max_error_rel": 0.02, "max_lateral_m": 0.01}]})");
  }
};

// Without --base the record names the physics files' robot.base (the shipped files say
// floating), not a placeholder; with --base, the flag's.
TEST_F(CheckCommandTest, TheJUnitRecordNamesTheBaseUsed) {
  const fs::path spec = OneCheckSpec();
  const RunResult files = Run({"check", "--spec", spec.string(), "--junit", "files.xml"});
  ASSERT_EQ(files.exit_code, 0) << files.err;
  EXPECT_THAT(ReadFile(work() / "files.xml"),
              HasSubstr("<property name=\"robot_base\" value=\"floating\"/>"));
  const RunResult fixed =
      Run({"check", "--spec", spec.string(), "--junit", "fixed.xml", "--base", "fixed"});
  ASSERT_EQ(fixed.exit_code, 0) << fixed.err;
  EXPECT_THAT(ReadFile(work() / "fixed.xml"),
              HasSubstr("<property name=\"robot_base\" value=\"fixed\"/>"));
}

}  // namespace
