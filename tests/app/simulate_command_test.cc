// `foresight simulate` against the real binary: the JSON contract, byte-identical output for the
// same seed whatever the thread count, SVG and CSV files, and one-line errors for bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "models/outcome.h"
#include "tests/app/run_foresight.h"

namespace {

namespace fs = std::filesystem;
using foresight::testing::CountOf;
using foresight::testing::ReadFile;
using foresight::testing::RunResult;
using foresight::testing::ShippedSituation;
using ::testing::HasSubstr;
using ::testing::StartsWith;

class SimulateCommandTest : public foresight::testing::ForesightRun {
 protected:
  RunResult Simulate(std::vector<std::string> args) const {
    args.insert(args.begin(), "simulate");
    return Run(args);
  }
  std::vector<std::string> OpenGoal(const std::string& kick, int trials) const {
    return {"--situation", ShippedSituation("open_goal").string(),
            "--kick",      kick,
            "--trials",    std::to_string(trials)};
  }
};

TEST_F(SimulateCommandTest, JsonHasEveryTrialAndSharesThatAddUp) {
  std::vector<std::string> args = OpenGoal("forward", 4);
  args.push_back("--json");
  const RunResult r = Simulate(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["command"], "simulate");
  EXPECT_EQ(j["robot"], "nao");
  EXPECT_EQ(j["trials_detail"].size(), 4u);
  double total = 0.0;
  for (const auto& [name, share] : j["summary"]["category_shares"].items())
    total += share.get<double>();
  EXPECT_DOUBLE_EQ(total, 1.0);
  EXPECT_EQ(j["summary"]["touched"], 4);
}

TEST_F(SimulateCommandTest, SameSeedSameBytesWithOneThreadOrTwo) {
  std::vector<std::string> args = OpenGoal("side_kick_left", 4);
  args.insert(args.end(), {"--json", "--seed", "17", "--svg", "rest.svg", "--trace", "trace.csv",
                           "--view", "view.html"});
  std::vector<std::string> one = args, two = args;
  one.insert(one.end(), {"--threads", "1"});
  two.insert(two.end(), {"--threads", "2"});
  const RunResult a = Simulate(one);
  const std::string svg_a = ReadFile(work() / "rest.svg"), csv_a = ReadFile(work() / "trace.csv");
  const std::string view_a = ReadFile(work() / "view.html");
  const RunResult b = Simulate(two);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(svg_a, ReadFile(work() / "rest.svg"));
  EXPECT_EQ(csv_a, ReadFile(work() / "trace.csv"));
  EXPECT_EQ(view_a, ReadFile(work() / "view.html"));
  EXPECT_THAT(view_a, HasSubstr("foresight scene trace 1"));
  EXPECT_THAT(svg_a, HasSubstr("<svg"));
  EXPECT_THAT(csv_a, StartsWith("trial,t_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps\n"));
  EXPECT_GT(CountOf(csv_a, "\n3,"), 10);  // the fourth trial has a trajectory
}

// --view is checked before the trials run: a missing folder is one line, exit 2, no file.
TEST_F(SimulateCommandTest, ViewIntoAMissingFolderFailsBeforeTheTrials) {
  std::vector<std::string> args = OpenGoal("forward", 2);
  args.insert(args.end(), {"--svg", "rest.svg", "--view", "missing/v.html"});
  const RunResult r = Simulate(args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "foresight: error: --view: missing/v.html: cannot write: directory missing "
                   "does not exist\n");
  EXPECT_FALSE(fs::exists(work() / "rest.svg"));  // nothing written: the run never started
  EXPECT_EQ(r.out, "");
  const RunResult rate = Simulate({"--situation", ShippedSituation("open_goal").string(), "--kick",
                                   "forward", "--view", "v.html", "--view-rate", "0"});
  EXPECT_EQ(rate.exit_code, 2);
  EXPECT_THAT(rate.err, HasSubstr("--view-rate"));
}

// Every trial's scene is kept until the view is written: trials times rate is capped before the
// trials run (100 trials at 1000 Hz took 522 MB), with the numbers and what to change.
TEST_F(SimulateCommandTest, AViewOfTooManyFramesIsRefusedBeforeTheTrials) {
  std::vector<std::string> args = OpenGoal("forward", 100);
  args.insert(args.end(), {"--view", "v.html", "--view-rate", "1000"});
  const RunResult r = Simulate(args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "foresight: error: --view: 100 trials at 1000 Hz are 100000 frames per simulated "
            "second, at most 20000 (every trial's scene is kept until the page is written): "
            "fewer --trials or a lower --view-rate\n");
  EXPECT_FALSE(fs::exists(work() / "v.html"));
  std::vector<std::string> many = OpenGoal("forward", 101);
  many.insert(many.end(), {"--view", "v.html"});
  const RunResult trials = Simulate(many);
  EXPECT_EQ(trials.exit_code, 2);
  EXPECT_EQ(trials.err,
            "foresight: error: --view: replays at most 100 trials (every trial's scene is kept "
            "until the page is written), got --trials 101\n");
}

// --view-rate sets the frames of --view only: without --view it would be ignored, so it is
// refused, as every flag without the flag it belongs to.
TEST_F(SimulateCommandTest, ViewRateWithoutViewIsRefused) {
  std::vector<std::string> args = OpenGoal("forward", 2);
  args.insert(args.end(), {"--view-rate", "50"});
  const RunResult r = Simulate(args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "foresight: error: --view-rate needs --view\n");
  EXPECT_EQ(r.out, "");
}

// On a floating base the robot stands on its feet: the JSON names the base and says per trial
// whether it fell and how far its torso tilted; the fixed base reports no tilt at all.
TEST_F(SimulateCommandTest, JsonNamesTheBaseAndEachTrialsFallAndTilt) {
  for (const char* base : {"fixed", "floating"}) {
    std::vector<std::string> args = OpenGoal("forward", 2);
    args.insert(args.end(), {"--json", "--base", base});
    const RunResult r = Simulate(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["base"], base);
    EXPECT_EQ(j["summary"]["fell"], 0) << base;
    EXPECT_EQ(j["summary"]["blocked"], 0) << base;  // nothing stands near the open goal's ball
    for (const auto& trial : j["trials_detail"]) {
      EXPECT_EQ(trial["fell"], false);
      EXPECT_EQ(trial["blocked"], false);
      // The status by its name, which reads back as a status.
      const std::optional<foresight::OutcomeStatus> status =
          foresight::ParseOutcomeStatus(trial["status"].get<std::string>());
      ASSERT_TRUE(status.has_value()) << trial["status"];
      EXPECT_EQ(*status, trial["touched"] ? foresight::OutcomeStatus::kOk
                                          : foresight::OutcomeStatus::kMissed);
      if (std::string(base) == "fixed") {
        EXPECT_EQ(trial["max_tilt_deg"], 0.0);
      } else {
        EXPECT_GT(trial["max_tilt_deg"].get<double>(), 0.0);  // a standing robot sways
        EXPECT_LT(trial["max_tilt_deg"].get<double>(), 20.0);
      }
    }
  }
}

struct BadSimulate {
  std::string name;
  std::vector<std::string> extra;  // after --situation open_goal
  std::string message;
};

void PrintTo(const BadSimulate& c, std::ostream* os) {
  *os << c.name;
}

class SimulateErrorTest : public SimulateCommandTest,
                          public ::testing::WithParamInterface<BadSimulate> {};

TEST_P(SimulateErrorTest, OneLineExitTwoNothingWritten) {
  std::vector<std::string> args = {"--situation", ShippedSituation("open_goal").string(), "--svg",
                                   "out.svg"};
  args.insert(args.end(), GetParam().extra.begin(), GetParam().extra.end());
  const RunResult r = Simulate(args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_THAT(r.err, StartsWith("foresight: error: "));
  EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr(GetParam().message));
  EXPECT_TRUE(Listing().empty());
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SimulateErrorTest,
    ::testing::Values(
        BadSimulate{"UnknownKick", {"--kick", "bicycle"}, "--kick: no kick 'bicycle'"},
        BadSimulate{"ZeroTrials", {"--kick", "forward", "--trials", "0"}, "--trials: must be"},
        BadSimulate{"TextTrials", {"--kick", "forward", "--trials", "many"}, "got 'many'"},
        BadSimulate{"NanRotation", {"--kick", "forward", "--rotation", "nan"}, "--rotation"},
        BadSimulate{"MissingPhysics", {"--kick", "forward", "--physics", "nope.json"}, "nope.json"},
        BadSimulate{"NegativeThreads", {"--kick", "forward", "--threads", "-1"}, "--threads"},
        BadSimulate{"UnknownBase",
                    {"--kick", "forward", "--base", "bolted"},
                    "--base: must be one of fixed, floating, got 'bolted'"}),
    [](const ::testing::TestParamInfo<BadSimulate>& info) { return info.param.name; });

}  // namespace

// Into a log (stderr not a terminal) progress comes as whole lines with the rate and the time
// left; FORESIGHT_PROGRESS_INTERVAL_S=0 writes one per report instead of one every few seconds,
// so the test needs no real time. A run shorter than the interval (an hour) writes none.
TEST_F(SimulateCommandTest, ALogGetsProgressLines) {
  ::setenv("FORESIGHT_PROGRESS_INTERVAL_S", "0", 1);
  const RunResult r = Simulate(OpenGoal("forward", 6));
  ::unsetenv("FORESIGHT_PROGRESS_INTERVAL_S");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(CountOf(r.err, "\r"), 0);
  EXPECT_EQ(CountOf(r.err, "simulate: "), 6) << r.err;  // one per trial: 6 reports
  EXPECT_THAT(r.err, HasSubstr("simulate: 1 / 6 trials (16 %), "));
  EXPECT_THAT(r.err, HasSubstr(" trials/s, about "));
  EXPECT_THAT(r.err, HasSubstr("simulate: 6 / 6 trials (100 %), done in "));
  ::setenv("FORESIGHT_PROGRESS_INTERVAL_S", "3600", 1);
  const RunResult quiet = Simulate(OpenGoal("forward", 6));
  ::unsetenv("FORESIGHT_PROGRESS_INTERVAL_S");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
}
