// `experiment passing` and `experiment ablations` in shards (--shard I/N) against the real
// binary: shards merged by `foresight merge` write the files of the unsharded run byte for byte
// (run time aside) and print its text, for 1, 2 and 3 shards; a shard of another run (seed,
// parameters, version, command), a missing and a duplicated one end in one line and exit 2,
// with no report.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/app/run_foresight.h"

namespace {

namespace fs = std::filesystem;
using foresight::testing::CountOf;
using foresight::testing::ReadFile;
using foresight::testing::ReplaceOnce;
using foresight::testing::ReportDifference;
using foresight::testing::RunResult;
using ::testing::HasSubstr;

class PassingShardCommandTest : public foresight::testing::ForesightRun {
 protected:
  // Runs `args` as shards 0 .. count - 1 into NAME-I and returns the folders.
  std::vector<std::string> Shards(const std::string& name, std::vector<std::string> args,
                                  int count) const {
    std::vector<std::string> dirs;
    for (int i = 0; i < count; ++i) {
      dirs.push_back(name + "-" + std::to_string(i));
      std::vector<std::string> shard = args;
      shard.insert(shard.end(), {"--threads", "1", "--shard", std::to_string(i) + "/" +
                                 std::to_string(count), "--out", dirs.back()});
      const RunResult r = Run(shard);
      EXPECT_EQ(r.exit_code, 0) << r.err;
      EXPECT_THAT(r.out, HasSubstr("shard " + std::to_string(i) + "/" + std::to_string(count)));
    }
    return dirs;
  }
  RunResult Merge(const std::string& out, const std::vector<std::string>& dirs) const {
    std::vector<std::string> args = {"merge", "--out", out};
    args.insert(args.end(), dirs.begin(), dirs.end());
    return Run(args);
  }
  // The unsharded run and 1, 2 and 3 shards merged: the same files and terminal text.
  void ExpectMergedEqualsWhole(const std::vector<std::string>& args) const {
    std::vector<std::string> whole = args;
    whole.insert(whole.end(), {"--threads", "2", "--out", "whole"});
    const RunResult w = Run(whole);
    ASSERT_EQ(w.exit_code, 0) << w.err;
    for (int count : {1, 2, 3}) {
      const std::string merged = "merged" + std::to_string(count);
      const RunResult m = Merge(merged, Shards("s" + std::to_string(count), args, count));
      ASSERT_EQ(m.exit_code, 0) << m.err;
      EXPECT_EQ(ReportDifference(work() / "whole", work() / merged), "") << count << " shards";
      // The text but its last line, which names the folder.
      EXPECT_EQ(m.out.substr(0, m.out.rfind("figures and data")),
                w.out.substr(0, w.out.rfind("figures and data")));
    }
  }
  void ExpectMergeFails(const std::vector<std::string>& dirs, const std::string& message) const {
    const RunResult r = Merge("out", dirs);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err, "foresight: error: " + message + "\n");
    EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
    EXPECT_FALSE(fs::exists(work() / "out")) << "a failed merge must not leave a folder";
  }
};

const std::vector<std::string> kPassing = {"experiment", "passing", "--config", "dg", "--team",
                                           "both", "--scenarios", "1,4", "--trials", "4"};

TEST_F(PassingShardCommandTest, PassingOfBothTeamsMergedEqualsTheUnshardedRun) {
  ExpectMergedEqualsWhole(kPassing);
  // The files of both teams, their examples and replays and the comparison, all compared.
  EXPECT_EQ(ReadFile(work() / "whole" / "passing_comparison.json").empty(), false);
  EXPECT_TRUE(fs::exists(work() / "merged3" / "passing_cbr_replay_dg_4.html"));
}

TEST_F(PassingShardCommandTest, AblationsMergedEqualsTheUnshardedRun) {
  ExpectMergedEqualsWhole({"experiment", "ablations", "--config", "2d", "--scenarios", "3",
                           "--trials", "3", "--mirror", "--seed", "5"});
  EXPECT_TRUE(fs::exists(work() / "merged2" / "ablations.svg"));
}

TEST_F(PassingShardCommandTest, ShardsOfAnotherRunAMissingOrADuplicatedOneAreRefused) {
  const std::vector<std::string> run = Shards("s", kPassing, 2);
  const auto other = [&](const std::string& name, std::vector<std::string> args) {
    return Shards(name, std::move(args), 2)[1];
  };
  std::vector<std::string> seed = kPassing;
  seed.insert(seed.end(), {"--seed", "2"});
  ExpectMergeFails({run[0], other("seed", seed)},
                   "seed-1/shard.json: setting --seed is '2', but s-0/shard.json has '1' "
                   "(shards of different runs)");
  std::vector<std::string> mirror = kPassing;
  mirror.push_back("--mirror");
  ExpectMergeFails({run[0], other("mirror", mirror)},
                   "mirror-1/shard.json: setting --mirror is 'true', but s-0/shard.json has "
                   "'false' (shards of different runs)");
  std::vector<std::string> trials = kPassing;
  trials[9] = "5";
  ExpectMergeFails({run[0], other("trials", trials)},
                   "trials-1/shard.json: the item count is '20', but s-0/shard.json has '16' "
                   "(shards of different runs)");
  ExpectMergeFails({run[0], other("ablations", {"experiment", "ablations", "--config", "dg",
                                                 "--scenarios", "1", "--trials", "1"})},
                   "ablations-1/shard.json: command is 'experiment ablations', but "
                   "s-0/shard.json has 'experiment passing' (shards of different runs)");
  ExpectMergeFails({run[1]}, "merge: shard(s) 0 of this 'experiment passing' run (0 .. 1) "
                             "missing; 1 folders given");
  ExpectMergeFails({run[0], run[1], run[0]},
                   "s-0/shard.json: shard 0/2 is given twice (also s-0/shard.json)");
  // A shard made by another version of foresight.
  fs::copy(work() / run[1], work() / "old");
  const fs::path old = work() / "old" / "shard.json";
  const std::string text = ReadFile(old);
  const std::size_t at = text.find("\"foresight_version\": \"");
  ASSERT_NE(at, std::string::npos);
  const std::string version = text.substr(at + 22, text.find('"', at + 22) - at - 22);
  std::ofstream(old) << ReplaceOnce(text, "\"foresight_version\": \"" + version + "\"",
                                    "\"foresight_version\": \"0.0.1\"");
  ExpectMergeFails({run[0], "old"}, "old/shard.json: foresight_version is '0.0.1', but "
                                    "s-0/shard.json has '" + version +
                                    "' (shards of different runs)");
  // The whole set merges.
  EXPECT_EQ(Merge("out", run).exit_code, 0);
}

TEST_F(PassingShardCommandTest, ABadShardFlagIsOneLineExitTwoAndNoFolder) {
  std::vector<std::string> args = kPassing;
  args.insert(args.end(), {"--shard", "2/2", "--out", "out"});
  const RunResult r = Run(args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "foresight: error: --shard: must be I/N with 0 <= I < N <= 100000 (shard I "
                   "of N), got '2/2'\n");
  EXPECT_FALSE(fs::exists(work() / "out"));
}

}  // namespace
