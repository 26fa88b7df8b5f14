// `foresight merge` against the real binary with shards that were damaged or edited after their
// run: every value is checked against what the command that wrote it can produce, so the merge
// ends in one line naming the shard file, the place in it and the value, exit 2, and writes
// nothing (it crashed on a trace frame without robots, and wrote p_infield -5 and a kick model
// with a 63-digit deceleration from numbers no run can produce).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/app/run_foresight.h"

namespace {

namespace fs = std::filesystem;
using foresight::testing::CountOf;
using foresight::testing::ReadFile;
using foresight::testing::RunResult;
using ::testing::HasSubstr;
using ::testing::StartsWith;

class MergeCommandTest : public foresight::testing::ForesightRun {
 protected:
  // Runs `args` as the single shard 0/1 into `dir`.
  void Shard(const std::string& dir, std::vector<std::string> args) const {
    args.insert(args.end(), {"--threads", "2", "--shard", "0/1", "--out", dir});
    const RunResult r = Run(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  // Edits DIR/shard.json with `edit` and merges it: the one-line error (or "(merged)").
  std::string MergeEdited(const std::string& dir,
                          const std::function<void(nlohmann::json&)>& edit) const {
    const fs::path file = work() / dir / "shard.json";
    nlohmann::json shard = nlohmann::json::parse(ReadFile(file));
    edit(shard);
    std::ofstream(file) << shard.dump(1);
    const RunResult r = Run({"merge", "--out", "merged", dir});
    if (r.exit_code == 0) return "(merged)";
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
    EXPECT_FALSE(fs::exists(work() / "merged")) << "a failed merge must not leave a folder";
    return r.err;
  }
};

TEST_F(MergeCommandTest, APassingTraceFrameWithoutEveryRobotIsRefused) {
  Shard("p", {"experiment", "passing", "--config", "dg", "--team", "reactive", "--scenarios", "1",
              "--trials", "1"});
  for (const int robots : {0, 1, 3}) {
    const std::string error = MergeEdited("p", [&](nlohmann::json& shard) {
      nlohmann::json& frame = shard["results"][0]["result"]["trace"][1];
      frame[3].erase(frame[3].begin() + robots, frame[3].end());
    });
    EXPECT_EQ(error, "foresight: error: p/shard.json: results[0].result.trace[1][3]: must list "
                     "every robot of the scenario (4), got " + std::to_string(robots) + "\n");
    Shard("p", {"experiment", "passing", "--config", "dg", "--team", "reactive", "--scenarios",
                "1", "--trials", "1"});
  }
}

TEST_F(MergeCommandTest, ACalibrationSampleNoTrialCanProduceIsRefused) {
  Shard("c", {"calibrate", "--robot", "nao", "--kick", "forward", "--trials", "8"});
  const std::string error = MergeEdited("c", [](nlohmann::json& shard) {
    shard["results"][0]["kicks"][0][3][1] = 1e308;  // a speed of the deceleration fit
  });
  EXPECT_THAT(error, StartsWith("foresight: error: c/shard.json: results[0].kicks[0][3][1]: "
                                "must be in [0, 50], got "));
}

TEST_F(MergeCommandTest, ARunTimeNoRunTakesIsRefused) {
  Shard("c", {"calibrate", "--robot", "nao", "--kick", "forward", "--trials", "8"});
  EXPECT_THAT(MergeEdited("c", [](nlohmann::json& shard) { shard["run_time_s"] = 1e308; }),
              HasSubstr("c/shard.json: run_time_s: must be in [0, 1e+09], got "));
}

// On the fixed base, the cheap approximation: what is merged does not depend on the base, and the
// quick set's 432 trials per shard run cost a tenth of the floating base's.
TEST_F(MergeCommandTest, AFidelityShareThatIsNotItsCountIsRefused) {
  Shard("f", {"fidelity", "--situations", "quick", "--trials", "2", "--converged", "40", "--base",
              "fixed"});
  const std::string error = MergeEdited("f", [](nlohmann::json& shard) {
    shard["results"][0]["candidates"][0]["coarse"]["p"] = {-5, 7, 0, 0};
  });
  EXPECT_THAT(error, StartsWith("foresight: error: f/shard.json: "
                                "results[0].candidates[0].coarse.p[0]: must be its count / "
                                "samples, "));
  // And the untouched shard merges.
  Shard("f", {"fidelity", "--situations", "quick", "--trials", "2", "--converged", "40", "--base",
              "fixed"});
  EXPECT_EQ(MergeEdited("f", [](nlohmann::json&) {}), "(merged)");
}

TEST_F(MergeCommandTest, AnOutThatIsOrHoldsAShardFolderIsRefusedAndTheShardKept) {
  Shard("runs/p", {"experiment", "passing", "--config", "dg", "--team", "reactive",
                   "--scenarios", "1", "--trials", "1"});
  const std::string shard = ReadFile(work() / "runs" / "p" / "shard.json");
  for (const std::string& out :
       {std::string("runs/p"), std::string("./runs/p/"), std::string("runs")}) {
    const RunResult r = Run({"merge", "--out", out, "runs/p"});
    EXPECT_EQ(r.exit_code, 2) << out;
    EXPECT_EQ(r.err, "foresight: error: --out: " + out + (out == "runs" ? " holds" : " is") +
                         " the shard folder runs/p, which the output would replace; write the "
                         "output elsewhere\n");
    EXPECT_EQ(ReadFile(work() / "runs" / "p" / "shard.json"), shard) << out;
  }
  EXPECT_EQ(Run({"merge", "--out", "runs/report", "runs/p"}).exit_code, 0);
}

// A merged calibration is one folder, --out: its refusals name --out (they named --report, a flag
// merge does not have) and come before the shards are read.
TEST_F(MergeCommandTest, AMergedCalibrationNamesOnlyItsOwnFlag) {
  Shard("c", {"calibrate", "--robot", "nao", "--kick", "forward", "--trials", "8"});
  fs::create_directories(work() / "mine");
  Write("mine/notes.txt", "the user's");
  const RunResult r = Run({"merge", "--out", "mine", "c"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, StartsWith("foresight: error: --out: mine: holds files that no foresight "
                                "report wrote"));
  EXPECT_EQ(ReadFile(work() / "mine" / "notes.txt"), "the user's");
  const RunResult merged = Run({"merge", "--out", "merged", "c"});
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_TRUE(fs::exists(work() / "merged" / "nao_calibrated.json"));
  EXPECT_TRUE(fs::exists(work() / "merged" / "calibration.html"));
}

// --out is checked before a shard is read: an --out that cannot be made is the error, not the
// shards (here missing).
TEST_F(MergeCommandTest, OutIsCheckedBeforeTheShardsAreRead) {
  Write("a_file", "x");
  const RunResult r = Run({"merge", "--out", "a_file/report", "missing_shard"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, StartsWith("foresight: error: --out: cannot create the folder "
                                "'a_file/report': "));
}

}  // namespace
