// A command's outputs as one set: located and checked before the work, written all or none, and
// two runs into the same outputs never leave a mix.
#include "report/output_set.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <barrier>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "common/data_file.h"
#include "common/error.h"
#include "common/input_log.h"
#include "tests/support/model_test_util.h"

namespace foresight {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::set<std::string> Names(const fs::path& dir) {
  return testing::FolderNames(dir);
}

template <typename Action>
std::string ErrorOf(Action&& action) {
  return testing::InputErrorMessage(action);
}

TEST(OutputSetTest, EveryOutputIsCheckedWhenDeclaredBeforeAnyWork) {
  const fs::path dir = testing::FreshTempDir("declared");
  OutputSet outputs;
  outputs.AddFile("--svg", dir / "a.svg");
  EXPECT_THAT(ErrorOf([&] { outputs.AddFile("--trace", dir / "missing" / "b.csv"); }),
              HasSubstr("--trace: " + (dir / "missing" / "b.csv").string()));
  EXPECT_THAT(ErrorOf([&] { outputs.AddFile("--trace", dir / "a.svg"); }),
              HasSubstr("is also --svg"));
  EXPECT_THAT(ErrorOf([&] { outputs.AddFile("--junit", dir); }), HasSubstr("is a directory"));
  EXPECT_TRUE(Names(dir).empty()) << "a check left something behind";
}

TEST(OutputSetTest, AFileInsideAReportFolderBecomesOneOfItsFiles) {
  const fs::path dir = testing::FreshTempDir("member") / "report";
  OutputSet outputs;
  outputs.AddFolder("--report", dir);
  outputs.AddFile("--out", dir / "model.json");  // the folder need not exist yet
  outputs.Put("--report", std::vector<ReportFile>{{"report.html", "<html/>"}});
  outputs.Put("--out", "{}");
  outputs.Commit();
  EXPECT_EQ(testing::ReadText(dir / "model.json"), "{}");
  EXPECT_THAT(testing::ReadText(dir / kReportMarker), HasSubstr("\nmodel.json\n"));
  OutputSet nested;
  nested.AddFolder("--report", dir);
  EXPECT_THAT(ErrorOf([&] { nested.AddFile("--out", dir / "sub" / "model.json"); }),
              HasSubstr("sub-folders"));
}

// With an InputLog open, no output may replace a file the run read: declared after the read,
// it is refused at once; read after the outputs were declared, the commit refuses it and
// writes nothing. An allowed file may be replaced.
TEST(OutputSetTest, AFileTheRunReadIsRefusedWhenDeclaredOrAtCommit) {
  const fs::path dir = testing::FreshTempDir("read_inputs");
  { std::ofstream(dir / "params.json") << "{}"; }
  WriteReportFolder(dir / "report", std::vector<ReportFile>{{"old.html", "x"}}, "--out");
  { std::ofstream(dir / "report" / "cases.json") << "{}"; }  // a user's file in the report
  const InputLog log;
  ReadDataFile(dir / "params.json");
  OutputSet early;
  EXPECT_EQ(ErrorOf([&] { early.AddFile("--out", dir / "params.json"); }),
            "--out: " + (dir / "params.json").string() +
                " is a file this run read, which the output would replace; write the output "
                "elsewhere");
  OutputSet late;
  late.AddFolder("--out", dir / "report");
  late.Put("--out", std::vector<ReportFile>{{"index.html", "x"}});
  ReadDataFile(dir / "report" / "cases.json");
  EXPECT_EQ(ErrorOf([&] { late.Commit(); }),
            "--out: " + (dir / "report").string() + " holds " +
                (dir / "report" / "cases.json").string() +
                ", a file this run read, which the output would replace; write the output "
                "elsewhere");
  EXPECT_FALSE(fs::exists(dir / "report" / "index.html"));
  EXPECT_TRUE(fs::exists(dir / "report" / "old.html"));
  InputLog::Allow(dir / "params.json");
  OutputSet allowed;
  allowed.AddFile("--out", dir / "params.json");
  allowed.Put("--out", std::string("{\"new\": 1}"));
  allowed.Commit();
  std::ifstream in(dir / "params.json");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "{\"new\": 1}");
}

// An output may not name an input: a file that is one, or a report folder that is or holds one
// (through a symbolic link too), in whichever order the two are declared.
TEST(OutputSetTest, AnOutputThatIsOrHoldsAnInputIsRefused) {
  const fs::path dir = testing::FreshTempDir("inputs");
  fs::create_directories(dir / "runs" / "shard");
  { std::ofstream(dir / "log.csv") << "kick\n"; }
  fs::create_directory_symlink(dir / "runs", dir / "link");
  const auto refusal = [&](const std::string& what, const fs::path& input, bool folder,
                           const fs::path& output, bool input_first) {
    try {
      OutputSet outputs;
      if (input_first) outputs.AddInput(what, input);
      folder ? outputs.AddFolder("--out", output) : outputs.AddFile("--out", output);
      if (!input_first) outputs.AddInput(what, input);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  for (const bool input_first : {true, false}) {
    EXPECT_EQ(refusal("the input --from-csv", dir / "log.csv", false, dir / "log.csv", input_first),
              "--out: " + (dir / "log.csv").string() + " is the input --from-csv " +
                  (dir / "log.csv").string() +
                  ", which the output would replace; write the output elsewhere");
    EXPECT_THAT(
        refusal("the shard folder", dir / "runs" / "shard", true, dir / "runs/shard/", input_first),
        HasSubstr("runs/shard/ is the shard folder"));
    // (A link as a report folder is refused anyway, but not before the input is named.)
    if (input_first) {
      EXPECT_THAT(refusal("the shard folder", dir / "runs" / "shard", true, dir / "link", true),
                  HasSubstr("link holds the shard folder"));
    }
    // A report beside the input, or inside an input folder, replaces nothing of it.
    EXPECT_EQ(refusal("the shard folder", dir / "runs" / "shard", true, dir / "runs" / "report",
                      input_first),
              "");
    EXPECT_EQ(refusal("the shard folder", dir / "runs" / "shard", true,
                      dir / "runs" / "shard" / "report", input_first),
              "");
  }
}

// A disk that fills up while the set is staged (here a file-size limit, RLIMIT_FSIZE, as
// `ulimit -f` sets it): no output is written, no temporary is left, and the message names the
// user's path, not the temporary's.
TEST(OutputSetTest, AFullDiskWritesNoOutputOfTheSetAndNamesTheUsersPath) {
  const fs::path dir = testing::FreshTempDir("full");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);  // write(2) fails with EFBIG instead of the signal ending us
    const rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    OutputSet outputs;
    outputs.AddFile("--out", dir / "model.json");
    outputs.AddFolder("--report", dir / "report");
    outputs.Put("--out", "small");
    outputs.Put("--report", std::vector<ReportFile>{{"big.html", std::string(100000, 'x')}});
    const std::string error = ErrorOf([&] { outputs.Commit(); });
    const bool names_path =
        error.find("--report: " + (dir / "report" / "big.html").string()) == 0 &&
        error.find(".tmp") == std::string::npos;
    ::_exit(names_path ? 0 : 1);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the error did not name --report's file";
  EXPECT_TRUE(Names(dir).empty()) << "an output or a temporary was left";
}

// Two runs writing the same two outputs, again and again at the same moment: after every round
// both outputs come from the same run (the commits take the folders' locks in turn).
TEST(OutputSetTest, ConcurrentSetsNeverLeaveOutputsOfDifferentRuns) {
  const fs::path dir = testing::FreshTempDir("concurrent_sets");
  constexpr int kRounds = 100;
  std::barrier round(3);  // the two writers and this thread, which looks after every round
  const auto writer = [&](const std::string& who) {
    for (int i = 0; i < kRounds; ++i) {
      round.arrive_and_wait();
      OutputSet outputs;
      outputs.AddFile("--out", dir / "model.json");
      outputs.AddFolder("--report", dir / "report");
      outputs.Put("--out", who + std::to_string(i));
      outputs.Put("--report", std::vector<ReportFile>{{"r.txt", who + std::to_string(i)}});
      outputs.Commit();
      round.arrive_and_wait();
    }
  };
  std::thread one(writer, "one"), two(writer, "two");
  int mixed = 0;
  for (int i = 0; i < kRounds; ++i) {
    round.arrive_and_wait();
    round.arrive_and_wait();
    mixed += testing::ReadText(dir / "model.json") != testing::ReadText(dir / "report" / "r.txt");
  }
  one.join();
  two.join();
  EXPECT_EQ(mixed, 0) << "rounds that left the model of one run and the report of the other";
  EXPECT_EQ(Names(dir), (std::set<std::string>{"model.json", "report"}));
}

}  // namespace
}  // namespace foresight
