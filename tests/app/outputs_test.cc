// Every command's outputs as one set (report/output_set.h) against the real binary: located and
// checked before the work, written together or not at all; and the command line's refusals of
// empty values, unknown commands and robots.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/app/run_foresight.h"

namespace {

namespace fs = std::filesystem;
using foresight::testing::CountOf;
using foresight::testing::Quote;
using foresight::testing::ReadFile;
using foresight::testing::RunResult;
using foresight::testing::ShippedSituation;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

class OutputsTest : public foresight::testing::ForesightRun {
 protected:
  // A one-line error, exit 2, and nothing new in the working folder.
  void ExpectRefused(const std::vector<std::string>& args, const std::string& message) {
    const auto before = Listing();
    const RunResult r = Run(args);
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_THAT(r.err, StartsWith("foresight: error: "));
    EXPECT_THAT(r.err, HasSubstr(message));
    EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
    EXPECT_EQ(Listing(), before);
  }

  // A log of 12 side kicks for `calibrate --from-csv` (fast: no physics).
  void WriteKickLog() const {
    std::string csv =
        "kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,ball_y_m,launch_speed_mps,"
        "launch_direction_deg,rest_x_m,rest_y_m\n";
    for (int i = 0; i < 12; ++i) {
      const double v = 0.5 + 0.02 * i, direction_deg = 84.0 + i;
      const double d = v * v / 0.6, a = direction_deg * 3.14159265358979 / 180.0;
      csv += "side_kick_left,0,0,0,0,0," + std::to_string(v) + "," +
             std::to_string(direction_deg) + "," + std::to_string(d * std::cos(a)) + "," +
             std::to_string(d * std::sin(a)) + "\n";
    }
    Write("kicks.csv", csv);
  }
};

// A million trials would run for hours: each of these ends at once because the outputs are
// checked before the work (they were checked after it).
TEST_F(OutputsTest, SimulateChecksEveryOutputBeforeTheTrials) {
  const std::string open_goal = ShippedSituation("open_goal").string();
  ExpectRefused({"simulate", "--situation", open_goal, "--kick", "forward", "--trials", "1000000",
                 "--svg", "a.svg", "--trace", "missing/b.csv"},
                "--trace: missing/b.csv");
  ExpectRefused({"simulate", "--situation", open_goal, "--kick", "forward", "--trials", "1000000",
                 "--svg", "same.svg", "--trace", "same.svg"},
                "is also --svg");
}

TEST_F(OutputsTest, CheckChecksItsJUnitFileBeforeTheChecks) {
  ExpectRefused({"check", "--junit", "missing/junit.xml"}, "--junit: missing/junit.xml");
}

TEST_F(OutputsTest, AReportParentThatCannotBeMadeIsFoundBeforeTheWork) {
  const std::string too_long(300, 'n');  // longer than a file name may be
  ExpectRefused({"calibrate", "--robot", "nao", "--kick", "forward", "--trials", "1000000",
                 "--out", "model.json", "--report", too_long + "/report"},
                "--report: cannot create the folder");
}

// Every other command's outputs are one OutputSet declared before the work too: an --out whose
// parent cannot be made ends each at once, however much work the flags ask for.
TEST_F(OutputsTest, EveryCommandChecksItsOutBeforeTheWork) {
  const std::string bad = std::string(300, 'n') + "/out";  // a name longer than a file's may be
  const std::string refused = "--out: cannot create the folder";
  ExpectRefused({"fidelity", "--situations", "quick", "--trials", "100000", "--out", bad}, refused);
  ExpectRefused({"experiment", "stability", "--repeats", "100000", "--out", bad}, refused);
  ExpectRefused({"experiment", "strategies", "--starts", "10000000", "--out", bad}, refused);
  ExpectRefused({"experiment", "passing", "--config", "dg", "--trials", "10000000", "--out", bad},
                refused);
  ExpectRefused({"experiment", "ablations", "--config", "dg", "--trials", "10000000", "--out", bad},
                refused);
  ExpectRefused({"cbr", "atlas", "--out", bad}, refused);
  // The same for a shard's folder.
  ExpectRefused({"calibrate", "--robot", "nao", "--kick", "forward", "--trials", "1000000",
                 "--shard", "0/2", "--out", bad},
                refused);
  ExpectRefused(
      {"fidelity", "--situations", "quick", "--trials", "100000", "--shard", "0/2", "--out", bad},
      refused);
  ExpectRefused(
      {"experiment", "strategies", "--starts", "10000000", "--shard", "0/2", "--out", bad},
      refused);
  ExpectRefused({"experiment", "passing", "--config", "dg", "--trials", "10000000", "--shard",
                 "1/3", "--out", bad},
                refused);
}

// An output may not replace one of the command's inputs: the log stays a log.
TEST_F(OutputsTest, AnOutputThatNamesAnInputIsRefused) {
  WriteKickLog();
  const std::string log = ReadFile(work() / "kicks.csv");
  ExpectRefused({"calibrate", "--robot", "nao", "--from-csv", "kicks.csv", "--out", "kicks.csv"},
                "--out: kicks.csv is the input --from-csv kicks.csv, which the output would "
                "replace");
  ExpectRefused({"calibrate", "--robot", "nao", "--from-csv", "kicks.csv", "--fit-variation",
                 "--out", "./kicks.csv"},
                "is the input --from-csv kicks.csv");
  EXPECT_EQ(ReadFile(work() / "kicks.csv"), log);
  Write("open_goal.json", foresight::testing::ShippedText("open_goal"));
  ExpectRefused({"simulate", "--situation", "open_goal.json", "--kick", "forward", "--trials",
                 "1000000", "--trace", "open_goal.json"},
                "--trace: open_goal.json is the input --situation open_goal.json");
  ExpectRefused({"decide", "--situation", "open_goal.json", "--svg", "open_goal.json"},
                "--svg: open_goal.json is the input --situation open_goal.json");
}

// A disk that fills up after the model is staged (a file-size limit, `ulimit -f`): neither the
// model nor the report is written, and the message names the user's file.
TEST_F(OutputsTest, CalibrateWritesTheModelAndTheReportTogetherOrNeither) {
  WriteKickLog();
  const std::string command =
      "cd " + Quote(work().string()) + " && (trap '' XFSZ; ulimit -f 16; exec " +
      Quote(FORESIGHT_BINARY) +
      " calibrate --robot nao --from-csv kicks.csv --out model.json --report report) "
      ">../capture/out 2>../capture/err";
  const int status = std::system(command.c_str());
  const std::string err = ReadFile(work() / ".." / "capture" / "err");
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << err;
  EXPECT_THAT(err, HasSubstr("--report: report/calibration"));
  EXPECT_THAT(err, Not(HasSubstr(".tmp")));
  EXPECT_FALSE(fs::exists(work() / "model.json")) << "the model was written without its report";
  EXPECT_FALSE(fs::exists(work() / "report"));
  // Without the limit both are written.
  const RunResult r = Run({"calibrate", "--robot", "nao", "--from-csv", "kicks.csv", "--out",
                           "model.json", "--report", "report"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(work() / "model.json"));
  EXPECT_TRUE(fs::exists(work() / "report" / "calibration.html"));
}

TEST_F(OutputsTest, AUsersFileInAReportFolderIsKept) {
  WriteKickLog();
  const std::vector<std::string> args = {"calibrate", "--robot",  "nao",   "--from-csv",
                                         "kicks.csv", "--out",    "model.json", "--report",
                                         "report"};
  ASSERT_EQ(Run(args).exit_code, 0);
  Write("report/my_notes.txt", "precious");
  const RunResult again = Run(args);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(ReadFile(work() / "report" / "my_notes.txt"), "precious");
}

// An empty value is refused, never read as "not given".
TEST_F(OutputsTest, EmptyValuesAreRefused) {
  const std::string open_goal = ShippedSituation("open_goal").string();
  ExpectRefused({"decide", "--situation", open_goal, "--svg", ""}, "--svg: empty value");
  ExpectRefused({"simulate", "--situation", open_goal, "--kick", "forward", "--trials", ""},
                "--trials: empty value");
  ExpectRefused({"check", "--spec", ""}, "--spec: empty value");
}

TEST_F(OutputsTest, AnUnknownCommandIsNamed) {
  ExpectRefused({"bogus"}, "unknown command 'bogus' (one of: decide, simulate");
  ExpectRefused({"--models", "x", "bogus"}, "unknown command 'bogus'");
}

TEST_F(OutputsTest, CalibrateRefusesUnknownRobotsAndStrayFlags) {
  ExpectRefused({"calibrate", "--robot", "bogus", "--all", "--out", "m.json"},
                "--robot: no robot 'bogus' in ");
  ExpectRefused({"calibrate", "--robot", "bogus", "--all", "--out", "m.json"},
                "(available: aibo_ers7, nao)");
  ExpectRefused({"calibrate", "--robot", "nao", "--all", "--fit-trials", "abc", "--out", "m.json"},
                "--fit-trials: only with --fit-variation");
}

}  // namespace
