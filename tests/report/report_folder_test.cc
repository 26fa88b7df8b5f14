// Report folders are replaced whole (issue 16): old or new, never a mix, never someone else's.
#include "report/report_folder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

namespace fs = std::filesystem;

fs::path FreshDir(const std::string& name) {
  return testing::FreshTempDir(name);
}

std::string Read(const fs::path& file) {
  return testing::ReadText(file);
}

std::set<std::string> Names(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
  return names;
}

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ReportFolderTest, ANewReportReplacesTheOldOneWhole) {
  const fs::path parent = FreshDir("replace");
  const fs::path dir = parent / "report";
  const std::vector<ReportFile> first = {{"a.json", "1"}, {"old.csv", "x"}};
  WriteReportFolder(dir, first, "--out");
  EXPECT_EQ(Names(dir), (std::set<std::string>{"a.json", "old.csv", std::string(kReportMarker)}));
  const std::vector<ReportFile> second = {{"a.json", "2"}};
  WriteReportFolder(dir, second, "--out");
  EXPECT_EQ(Names(dir), (std::set<std::string>{"a.json", std::string(kReportMarker)}));
  EXPECT_EQ(Read(dir / "a.json"), "2");
  EXPECT_EQ(Names(parent), (std::set<std::string>{"report"})) << "a temporary folder remains";
}

TEST(ReportFolderTest, AFolderOfTheUsersIsRefusedAndLeftAlone) {
  const fs::path dir = FreshDir("users");
  std::ofstream(dir / "thesis.tex") << "precious";
  const std::vector<ReportFile> files = {{"a.json", "1"}};
  EXPECT_THAT(ErrorOf([&] { CheckReportFolder(dir, "--out"); }),
              ::testing::HasSubstr("holds files that no foresight report wrote"));
  EXPECT_THAT(ErrorOf([&] { WriteReportFolder(dir, files, "--out"); }),
              ::testing::StartsWith("--out: " + dir.string()));
  EXPECT_EQ(Read(dir / "thesis.tex"), "precious");
  EXPECT_THAT(ErrorOf([&] { CheckReportFolder(".", "--out"); }),
              ::testing::HasSubstr("a report folder of its own"));
}

TEST(ReportFolderTest, AFailedWriteKeepsTheOldReportAndLeavesNoTemporary) {
  const fs::path parent = FreshDir("failed");
  const fs::path dir = parent / "report";
  const std::vector<ReportFile> good = {{"a.json", "old"}};
  WriteReportFolder(dir, good, "--out");
  const std::vector<ReportFile> bad = {{"a.json", "new"}, {"no_such_sub/b.json", "x"}};
  EXPECT_NE(ErrorOf([&] { WriteReportFolder(dir, bad, "--out"); }), "");
  EXPECT_EQ(Read(dir / "a.json"), "old");
  EXPECT_EQ(Names(parent), (std::set<std::string>{"report"}));
}

// Two writers into one folder: the result is one writer's report, every file from the same one.
TEST(ReportFolderTest, ConcurrentWritersNeverMix) {
  const fs::path dir = FreshDir("concurrent") / "report";
  const auto writer = [&](const std::string& who) {
    const std::vector<ReportFile> files = {{"a.txt", who}, {"b.txt", who}, {"c.txt", who}};
    for (int i = 0; i < 50; ++i) WriteReportFolder(dir, files, "--out");
  };
  std::thread one(writer, "one"), two(writer, "two");
  one.join();
  two.join();
  const std::string a = Read(dir / "a.txt");
  EXPECT_TRUE(a == "one" || a == "two");
  EXPECT_EQ(Read(dir / "b.txt"), a);
  EXPECT_EQ(Read(dir / "c.txt"), a);
  EXPECT_EQ(Names(dir.parent_path()), (std::set<std::string>{"report"}));
}

}  // namespace
}  // namespace foresight
