// `foresight experiment stability|strategies` against the real binary: tiny experiments write
// JSON, CSV and SVG; the same seed gives the same bytes with one thread or two; bad input is
// one line, exit code 2 and no folder.
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
using foresight::testing::RunResult;
using ::testing::HasSubstr;
using ::testing::StartsWith;

class ExperimentCommandTest : public foresight::testing::ForesightRun {
 protected:
  fs::path TinyStability() const {
    return Write("tiny_stability.json", R"({"situation": "experiment_nao", "strategy": "naoth",
        "grid_step_m": 2.0, "heading_step_deg": 120, "repeats": 10,
        "sample_counts": [1, 5, 30], "map_samples": 30, "rotation_bin_deg": 10})");
  }
  RunResult Experiment(std::vector<std::string> args) const {
    args.insert(args.begin(), "experiment");
    return Run(args);
  }
  static std::string WithoutRunTime(const std::string& json_text) {
    nlohmann::json j = nlohmann::json::parse(json_text);
    EXPECT_TRUE(j.contains("run_time_s"));
    j.erase("run_time_s");
    return j.dump();
  }
  void ExpectBadInput(const std::vector<std::string>& args, const std::string& message) const {
    const RunResult r = Experiment(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_THAT(r.err, StartsWith("foresight: error: "));
    EXPECT_THAT(r.err, HasSubstr(message));
    EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
    EXPECT_FALSE(fs::exists(work() / "out")) << "a failed run must not leave a folder";
  }
};

TEST_F(ExperimentCommandTest, StabilityWritesJsonCsvAndFigures) {
  const RunResult r = Experiment(
      {"stability", "--params", TinyStability().string(), "--out", "out", "--threads", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("out/stability.svg"));
  const fs::path dir = work() / "out";
  const nlohmann::json j = nlohmann::json::parse(ReadFile(dir / "stability.json"));
  EXPECT_EQ(j["experiment"], "stability");
  EXPECT_EQ(j["grid"]["positions"], 4 * 3);
  EXPECT_EQ(j["grid"]["poses"], 4 * 3 * 3);
  EXPECT_EQ(j["counts"].size(), 3u);
  EXPECT_EQ(j["decisions"], 36 * 3 * 10);
  EXPECT_EQ(j["params"]["strategy"], "naoth");
  EXPECT_EQ(CountOf(ReadFile(dir / "stability.csv"), "\n"), 1 + 3);
  EXPECT_EQ(CountOf(ReadFile(dir / "stability_positions.csv"), "\n"), 1 + 12);
  EXPECT_THAT(ReadFile(dir / "stability.svg"), HasSubstr("<svg"));
  EXPECT_THAT(ReadFile(dir / "stability_map.svg"), HasSubstr("<svg"));
}

TEST_F(ExperimentCommandTest, StabilityFlagsOverrideTheFile) {
  const RunResult r = Experiment({"stability", "--params", TinyStability().string(), "--samples",
                                  "2-4", "--repeats", "3", "--strategy", "fast", "--out", "out"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(ReadFile(work() / "out" / "stability.json"));
  EXPECT_EQ(j["params"]["samples_per_decision"], nlohmann::json::array({2, 3, 4}));
  EXPECT_EQ(j["params"]["map_samples"], 4);
  EXPECT_EQ(j["params"]["repeats"], 3);
  EXPECT_EQ(j["params"]["strategy"], "fast");
}

TEST_F(ExperimentCommandTest, StabilitySameBytesWithOneThreadOrTwo) {
  const std::string params = TinyStability().string();
  ASSERT_EQ(Experiment({"stability", "--params", params, "--out", "a", "--threads", "1"}).exit_code,
            0);
  ASSERT_EQ(Experiment({"stability", "--params", params, "--out", "b", "--threads", "2"}).exit_code,
            0);
  for (const char* file :
       {"stability.csv", "stability_positions.csv", "stability.svg", "stability_map.svg"}) {
    EXPECT_EQ(ReadFile(work() / "a" / file), ReadFile(work() / "b" / file)) << file;
  }
  EXPECT_EQ(WithoutRunTime(ReadFile(work() / "a" / "stability.json")),
            WithoutRunTime(ReadFile(work() / "b" / "stability.json")));
}

TEST_F(ExperimentCommandTest, StrategiesWriteJsonCsvAndFigures) {
  const RunResult r = Experiment({"strategies", "--starts", "6", "--out", "out"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path dir = work() / "out";
  const nlohmann::json j = nlohmann::json::parse(ReadFile(dir / "strategies.json"));
  EXPECT_EQ(j["params"]["starts"], 6);
  EXPECT_EQ(j["params"]["executor"], "coarse");
  // The kick model it used, by path and content hash.
  EXPECT_EQ(j["params"]["kicks"], "kicks/nao.json");
  EXPECT_THAT(j["params"]["kicks_hash"].get<std::string>(), ::testing::StartsWith("fnv1a64:"));
  ASSERT_EQ(j["strategies"].size(), 4u);
  EXPECT_EQ(j["strategies"][0]["strategy"], "fast");
  EXPECT_EQ(j["strategies"][0]["runs"], 6);
  EXPECT_TRUE(j["strategies"][1].contains("minus_fast"));
  EXPECT_EQ(CountOf(ReadFile(dir / "strategies_runs.csv"), "\n"), 1 + 4 * 6);
  for (const char* svg : {"strategies_turns.svg", "strategies_kicks.svg", "strategies_paths.svg"}) {
    EXPECT_THAT(ReadFile(dir / svg), HasSubstr("<svg")) << svg;
  }
}

TEST_F(ExperimentCommandTest, StrategiesSameBytesWithOneThreadOrTwo) {
  ASSERT_EQ(Experiment({"strategies", "--starts", "5", "--out", "a", "--threads", "1"}).exit_code,
            0);
  ASSERT_EQ(Experiment({"strategies", "--starts", "5", "--out", "b", "--threads", "2"}).exit_code,
            0);
  for (const char* file : {"strategies_runs.csv", "strategies_turns.svg", "strategies_kicks.svg",
                           "strategies_paths.svg"}) {
    EXPECT_EQ(ReadFile(work() / "a" / file), ReadFile(work() / "b" / file)) << file;
  }
  EXPECT_EQ(WithoutRunTime(ReadFile(work() / "a" / "strategies.json")),
            WithoutRunTime(ReadFile(work() / "b" / "strategies.json")));
}

TEST_F(ExperimentCommandTest, BadInputIsOneLineExitTwoAndNoFolder) {
  ExpectBadInput({"stability", "--quick", "--params", "stability", "--out", "out"},
                 "--quick and --params exclude each other");
  ExpectBadInput({"stability", "--quick", "--samples", "5-1", "--out", "out"}, "--samples: '5-1'");
  ExpectBadInput({"stability", "--quick", "--strategy", "greedy", "--out", "out"},
                 "--strategy: unknown strategy 'greedy'");
  ExpectBadInput({"stability", "--quick", "--repeats", "1", "--out", "out"}, "--repeats");
  ExpectBadInput({"strategies", "--starts", "0", "--out", "out"}, "--starts");
  ExpectBadInput({"strategies", "--physics-file", "x.json", "--out", "out"},
                 "--physics-file needs --physics");
  ExpectBadInput({"strategies", "--params", "nope", "--out", "out"}, "nope.json does not exist");
  ExpectBadInput({"strategies", "--kicks", "missing.json", "--out", "out"}, "missing.json");
}

// No output may replace a file the run read: --params kept in the report folder it would
// replace is refused before the work, and the folder and the file stay as they were.
TEST_F(ExperimentCommandTest, AnOutputHoldingAFileTheRunReadIsRefused) {
  ASSERT_EQ(Experiment({"stability", "--params", TinyStability().string(), "--out", "out"}).exit_code, 0);
  const std::string before = ReadFile(work() / "out" / "stability.json");
  fs::copy_file(TinyStability(), work() / "out" / "mine.json");
  const RunResult r = Experiment({"stability", "--params", "out/mine.json", "--out", "out"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--out: out holds "));
  EXPECT_THAT(r.err, HasSubstr("mine.json, a file this run read, which the output would replace"));
  EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
  EXPECT_EQ(ReadFile(work() / "out" / "stability.json"), before);
  EXPECT_TRUE(fs::exists(work() / "out" / "mine.json"));
}

TEST_F(ExperimentCommandTest, PassingWritesJsonCsvEventsAndFigures) {
  const RunResult r = Experiment({"passing", "--config", "dg", "--scenarios", "3-4", "--trials",
                                  "6", "--threads", "2", "--out", "out"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("reactive team against dg, 6 trials per scenario"));
  for (const char* file : {"passing.json", "passing_trials.csv", "passing_events.csv",
                           "passing_outcomes.svg", "passing_possession.svg", "passing_time.svg",
                           "passing_example_dg_3.svg", "passing_example_dg_4.svg",
                           "passing_replay_dg_3.html", "passing_replay_dg_4.html"}) {
    EXPECT_TRUE(fs::exists(work() / "out" / file)) << file;
  }
  const auto json = nlohmann::json::parse(ReadFile(work() / "out" / "passing.json"));
  EXPECT_EQ(json["scenarios"].size(), 2u);
  EXPECT_EQ(json["scenarios"][0]["trials"], 6);
  EXPECT_EQ(CountOf(ReadFile(work() / "out" / "passing_trials.csv"), "\n"), 1 + 12);
  const std::string replay = ReadFile(work() / "out" / "passing_replay_dg_3.html");
  EXPECT_THAT(replay, HasSubstr("const frames = [[0.00,"));
  for (const char* fetch : {"src=", "<link", "url(", "import "}) {  // self-contained
    EXPECT_THAT(replay, ::testing::Not(HasSubstr(fetch)));
  }
}

TEST_F(ExperimentCommandTest, PassingBadScenarioOrParameterFileIsOneLineExitTwoAndNoFolder) {
  const std::string dg = ReadFile(fs::path(FORESIGHT_TEST_MODELS_DIR) / "match" / "dg.json");
  const fs::path bad_time = Write(
      "bad_time.json", foresight::testing::ReplaceOnce(dg, "\"time_limit_s\": 600.0",
                                                       "\"time_limit_s\": -1"));
  ExpectBadInput({"passing", "--config", bad_time.string(), "--out", "out"},
                 bad_time.string() + ": time_limit_s: must be");
  const std::string scenario = ReadFile(fs::path(FORESIGHT_TEST_MODELS_DIR) / "match" / "scenarios" / "dg_1.json");
  Write("bad_scenario.json",
        foresight::testing::ReplaceOnce(scenario, "\"x_m\": -1.3", "\"x_m\": \"far\""));
  const fs::path config = Write(
      "config.json", foresight::testing::ReplaceOnce(dg, "\"dg_1\"", "\"bad_scenario.json\""));
  ExpectBadInput({"passing", "--config", config.string(), "--out", "out"},
                 "bad_scenario.json: ball.x_m: must be a number");
  ExpectBadInput({"passing", "--config", "dg", "--scenarios", "5", "--out", "out"},
                 "--scenarios: scenario 5 does not exist");
  ExpectBadInput({"passing", "--config", "dg", "--scenarios", "1,1", "--out", "out"},
                 "--scenarios: scenario 1 is listed twice");
  ExpectBadInput({"passing", "--config", "dg", "--team", "robots", "--out", "out"},
                 "--team: unknown team 'robots'");
  ExpectBadInput({"passing", "--config", "3d", "--out", "out"}, "3d.json");
  ExpectBadInput({"passing", "--config", "dg", "--physics-file", "x.json", "--out", "out"},
                 "--physics-file needs --physics");
  ExpectBadInput({"passing", "--config", "dg", "--kicks", "nao", "--out", "out"},
                 "the kick model is for robot 'nao'; the match plays AIBOs");
}

// --kicks replaces the simulation file's kick model: a stronger forward kick changes the game,
// and the report names the model used.
TEST_F(ExperimentCommandTest, PassingKicksOverrideIsPlayed) {
  nlohmann::json model = nlohmann::json::parse(
      ReadFile(fs::path(FORESIGHT_TEST_MODELS_DIR) / "kicks" / "aibo_ers7.json"));
  for (auto& kick : model["kicks"]) {
    if (kick["name"] == "forward") kick["speed_mps"] = 1.2;
  }
  const fs::path kicks = Write("strong.json", model.dump(2));
  const RunResult base = Experiment(
      {"passing", "--config", "dg", "--scenarios", "1", "--trials", "20", "--out", "base"});
  const RunResult r = Experiment({"passing", "--config", "dg", "--scenarios", "1", "--trials",
                                  "20", "--kicks", kicks.string(), "--out", "strong"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(base.exit_code, 0) << base.err;
  EXPECT_NE(ReadFile(work() / "base" / "passing_trials.csv"),
            ReadFile(work() / "strong" / "passing_trials.csv"));
  EXPECT_THAT(ReadFile(work() / "strong" / "passing.json"), HasSubstr("strong.json"));
}

// On the fixed base, the cheap approximation: what is tested is the executor and its report,
// and each kick of a match builds its own scene, which on the floating base settles the stance
// again.
TEST_F(ExperimentCommandTest, PassingWithPhysicsExecutesTheKicksInBullet) {
  const RunResult r = Experiment({"passing", "--config", "dg", "--scenarios", "4", "--trials",
                                  "2", "--physics", "--base", "fixed", "--out", "out"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(ReadFile(work() / "out" / "passing.json"));
  EXPECT_EQ(json["params"]["executor"], "physics");
  EXPECT_EQ(json["params"]["physics"], "physics/four_legged.json");
  EXPECT_TRUE(json["scenarios"][0].contains("kicks_missed"));
  EXPECT_TRUE(json["scenarios"][0].contains("kicks_blocked"));
  EXPECT_EQ(json["params"]["robot_base"], "fixed");
  // The example trial in 3D: the match, then each of its kicks as a recorded physics trial of
  // the AIBO (one per kick event of the trial).
  const std::string view = ReadFile(work() / "out" / "passing_view_dg_4.html");
  EXPECT_THAT(view, HasSubstr("\"label\":\"the match (example trial 0)\""));
  EXPECT_GE(CountOf(view, "\"label\":\"kick "), 1);
  EXPECT_THAT(view, HasSubstr("\"name\":\"aibo_ers7\""));
}

// A bad --out fails before the work: a file in the way of the folder.
TEST_F(ExperimentCommandTest, OutBlockedByAFileFailsBeforeTheWork) {
  Write("blocker", "x");
  for (const char* experiment : {"stability", "strategies"}) {
    const RunResult r =
        Experiment({experiment, experiment == std::string("stability") ? "--quick" : "--physics",
                    "--out", "blocker/out"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr("--out: cannot create the folder 'blocker/out'"));
    EXPECT_THAT(r.err, HasSubstr("is a file, not a folder"));
    EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
  }
}

}  // namespace

namespace {

// --team both: both teams' reports and the paired comparison, which names the teams.
TEST_F(ExperimentCommandTest, PassingBothTeamsWritesEachReportAndThePairedComparison) {
  const RunResult r = Experiment({"passing", "--config", "dg", "--team", "both", "--scenarios",
                                  "1", "--trials", "6", "--out", "both"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"passing_cbr.json", "passing_reactive.json", "passing_cbr_trials.csv",
                        "passing_reactive_replay_dg_1.html", "passing_comparison.json",
                        "passing_teams.svg"}) {
    EXPECT_TRUE(fs::exists(work() / "both" / f)) << f;
  }
  const nlohmann::json c = nlohmann::json::parse(ReadFile(work() / "both" / "passing_comparison.json"));
  EXPECT_EQ(c["first"], "cbr");
  EXPECT_EQ(c["second"], "reactive");
  EXPECT_TRUE(c["scenarios"][0]["measures"].contains("to_goal"));
  const nlohmann::json cbr = nlohmann::json::parse(ReadFile(work() / "both" / "passing_cbr.json"));
  EXPECT_EQ(cbr["params"]["team"], "cbr");
  EXPECT_GT(cbr["scenarios"][0]["team_counters"]["cases_retrieved"]["mean"].get<double>(), 0.0);
}

TEST_F(ExperimentCommandTest, AblationsPlayEveryVariantAndRejectABadVariantsFile) {
  const RunResult r = Experiment({"ablations", "--config", "dg", "--scenarios", "4", "--trials",
                                  "3", "--out", "abl"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(ReadFile(work() / "abl" / "ablations.json"));
  const nlohmann::json shipped = nlohmann::json::parse(
      ReadFile(fs::path(FORESIGHT_TEST_MODELS_DIR) / "experiments" / "cbr_variants.json"));
  EXPECT_EQ(j["variants"].size(), shipped["variants"].size());  // every shipped variant plays
  EXPECT_EQ(j["variants"][0]["name"], "paper");
  EXPECT_TRUE(fs::exists(work() / "abl" / "ablations.svg"));
  const fs::path bad = Write("variants.json",
                             R"({"variants": [{"name": "a", "simulation": {"message_loss_rate": 2}}]})");
  ExpectBadInput({"ablations", "--config", "dg", "--variants", bad.string(), "--out", "out"},
                 bad.string() + ": variants[0].simulation.message_loss_rate: must be within [0, 1]");
}

}  // namespace
