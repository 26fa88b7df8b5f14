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
#include "report/output_set.h"
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
  return testing::FolderNames(dir);
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

// A report folder given as a symbolic link is refused, saying so and naming the folder to give
// (it said "exists and is not a folder" of a link to a folder), and the link is left alone.
TEST(ReportFolderTest, AReportFolderGivenAsALinkIsRefusedNamingTheFolder) {
  const fs::path parent = FreshDir("linked");
  fs::create_directory(parent / "real");
  fs::create_directory_symlink("real", parent / "link");
  const std::string error = ErrorOf([&] { CheckReportFolder(parent / "link", "--out"); });
  EXPECT_THAT(error, ::testing::StartsWith("--out: " + (parent / "link").string()));
  EXPECT_THAT(error, ::testing::HasSubstr("is a symbolic link (to real): a report folder is "
                                          "replaced whole, give the folder itself"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(parent / "link")));
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

// The marker lists what foresight wrote; everything else in the folder is the user's and stays.
TEST(ReportFolderTest, TheMarkerListsTheReportsFilesAndTheUsersFilesAreKept) {
  const fs::path dir = FreshDir("kept") / "report";
  const std::vector<ReportFile> first = {{"a.json", "1"}, {"old.csv", "x"}};
  WriteReportFolder(dir, first, "--out");
  EXPECT_EQ(Read(dir / kReportMarker), std::string(kMarkerHeader) + "\na.json\nold.csv\n");
  std::ofstream(dir / "my_notes.txt") << "precious";
  fs::create_directory(dir / "my_plots");
  std::ofstream(dir / "my_plots" / "p.svg") << "<svg/>";
  const std::vector<ReportFile> second = {{"a.json", "2"}};
  WriteReportFolder(dir, second, "--out");
  EXPECT_EQ(Names(dir), (std::set<std::string>{"a.json", "my_notes.txt", "my_plots",
                                               std::string(kReportMarker)}));
  EXPECT_EQ(Read(dir / "a.json"), "2");
  EXPECT_EQ(Read(dir / "my_notes.txt"), "precious");
  EXPECT_EQ(Read(dir / "my_plots" / "p.svg"), "<svg/>");
  EXPECT_EQ(Read(dir / kReportMarker), std::string(kMarkerHeader) + "\na.json\n");
  EXPECT_EQ(Names(dir.parent_path()), (std::set<std::string>{"report"}));
}

TEST(ReportFolderTest, AnEmptyOrForeignMarkerDoesNotMakeAFolderForesights) {
  for (const std::string& marker : {std::string(), std::string("mine, not foresight's\n")}) {
    const fs::path dir = FreshDir("foreign_marker");
    std::ofstream(dir / kReportMarker) << marker;
    std::ofstream(dir / "thesis.tex") << "precious";
    const std::vector<ReportFile> files = {{"thesis.tex", "overwritten"}};
    EXPECT_THAT(ErrorOf([&] { CheckReportFolder(dir, "--out"); }),
                ::testing::HasSubstr("holds files that no foresight report wrote"));
    EXPECT_NE(ErrorOf([&] { WriteReportFolder(dir, files, "--out"); }), "");
    EXPECT_EQ(Read(dir / "thesis.tex"), "precious");
    EXPECT_EQ(Read(dir / kReportMarker), marker);
  }
}

TEST(ReportFolderTest, AUsersFileWithTheNameOfAReportFileIsRefusedNotReplaced) {
  const fs::path dir = FreshDir("clash") / "report";
  const std::vector<ReportFile> first = {{"a.json", "1"}};
  WriteReportFolder(dir, first, "--out");
  std::ofstream(dir / "b.json") << "the user's";
  const std::vector<ReportFile> second = {{"a.json", "2"}, {"b.json", "report"}};
  EXPECT_THAT(ErrorOf([&] { WriteReportFolder(dir, second, "--out"); }),
              ::testing::HasSubstr("'b.json', which foresight did not write"));
  EXPECT_EQ(Read(dir / "b.json"), "the user's");
  EXPECT_EQ(Read(dir / "a.json"), "1");
  EXPECT_EQ(Names(dir.parent_path()), (std::set<std::string>{"report"}));
}

// A report of the earlier marker ("the folder is replaced whole") is foresight's; of its files
// those the new report writes are replaced, the others kept (nothing says whose they are).
TEST(ReportFolderTest, AFolderWithTheEarlierMarkerIsReplacedKeepingWhatTheReportDoesNotWrite) {
  const fs::path dir = FreshDir("legacy") / "report";
  fs::create_directories(dir);
  std::ofstream(dir / kReportMarker) << "written by foresight; the folder is replaced whole\n";
  std::ofstream(dir / "a.json") << "old";
  std::ofstream(dir / "notes.txt") << "kept";
  const std::vector<ReportFile> files = {{"a.json", "new"}};
  WriteReportFolder(dir, files, "--out");
  EXPECT_EQ(Read(dir / "a.json"), "new");
  EXPECT_EQ(Read(dir / "notes.txt"), "kept");
}

TEST(ReportFolderTest, AParentThatCannotBeCreatedIsFoundBeforeTheWorkAndNothingIsLeft) {
  const fs::path parent = FreshDir("uncreatable");
  std::ofstream(parent / "a_file") << "x";
  EXPECT_THAT(ErrorOf([&] { CheckReportFolder(parent / "a_file" / "sub" / "report", "--out"); }),
              ::testing::HasSubstr("is a file, not a folder"));
  const std::string long_name(300, 'n');  // longer than NAME_MAX: mkdir refuses it
  EXPECT_THAT(ErrorOf([&] { CheckReportFolder(parent / long_name / "report", "--out"); }),
              ::testing::HasSubstr("cannot create the folder"));
  CheckReportFolder(parent / "new" / "deeper" / "report", "--out");  // creatable: made, removed
  EXPECT_EQ(Names(parent), (std::set<std::string>{"a_file"}));
}

}  // namespace
}  // namespace foresight
