// `foresight calibrate` against the real binary: the written kick model and report, the same
// bytes whatever the thread count, observed kicks from CSV, and one-line errors that write
// nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "common/geometry.h"
#include "models/kick_model.h"
#include "tests/app/run_foresight.h"

namespace {

namespace fs = std::filesystem;
using foresight::KickModel;
using foresight::KickSpec;
using foresight::LoadKickModel;
using foresight::testing::CountOf;
using foresight::testing::ReadFile;
using foresight::testing::RunResult;
using ::testing::HasSubstr;
using ::testing::StartsWith;

KickModel ShippedNao() {
  return LoadKickModel(std::filesystem::path(FORESIGHT_TEST_MODELS_DIR) / "kicks" / "nao.json");
}

class CalibrateCommandTest : public foresight::testing::ForesightRun {
 protected:
  RunResult Calibrate(std::vector<std::string> args) const {
    args.insert(args.begin(), "calibrate");
    return Run(args);
  }
  // On the fixed base, the cheap approximation (a tenth of a floating trial's cost): these tests
  // are of the command's files, bytes and errors, which do not depend on the base.
  static std::vector<std::string> SideKick(const std::string& threads) {
    return {"--robot", "nao",   "--kick",      "side_kick_left", "--trials", "40",
            "--seed",  "3",     "--out",       "fitted.json",    "--report", "report",
            "--threads", threads, "--base",    "fixed"};
  }
};

TEST_F(CalibrateCommandTest, PhysicsCalibrationWritesModelAndReport) {
  const RunResult r = Calibrate(SideKick("2"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("report/calibration.html"));
  EXPECT_THAT(r.out, HasSubstr("fitted.json"));
  EXPECT_THAT(r.out, HasSubstr("side_kick_left"));

  const KickModel base = ShippedNao();
  const KickModel fitted = LoadKickModel(work() / "fitted.json");
  EXPECT_EQ(fitted.robot, "nao");
  EXPECT_NE(fitted.rolling_deceleration_mps2, base.rolling_deceleration_mps2);
  // The fitted deceleration is the carpet's (physics/spl.json), within a few per cent.
  EXPECT_NEAR(fitted.rolling_deceleration_mps2, base.rolling_deceleration_mps2,
              0.05 * base.rolling_deceleration_mps2);
  ASSERT_EQ(fitted.kicks.size(), base.kicks.size());
  for (std::size_t i = 0; i < base.kicks.size(); ++i) {
    const KickSpec& got = fitted.kicks[i];
    const KickSpec& was = base.kicks[i];
    ASSERT_EQ(got.name, was.name);
    if (was.name == "side_kick_left") {
      EXPECT_NE(got.speed_mps, was.speed_mps);
      EXPECT_NE(got.sigma_direction_rad, was.sigma_direction_rad);
      EXPECT_GT(got.speed_mps, 0.0);
      EXPECT_GT(got.sigma_speed_mps, 0.0);
      EXPECT_NEAR(got.direction_rad, 90.0 * foresight::kDegToRad, 10.0 * foresight::kDegToRad);
    } else {
      EXPECT_NEAR(got.speed_mps, was.speed_mps, 1e-12) << was.name;
      EXPECT_NEAR(got.sigma_speed_mps, was.sigma_speed_mps, 1e-12) << was.name;
      EXPECT_NEAR(got.direction_rad, was.direction_rad, 1e-12) << was.name;
      EXPECT_NEAR(got.sigma_direction_rad, was.sigma_direction_rad, 1e-12) << was.name;
    }
  }

  const fs::path report = work() / "report";
  const nlohmann::json j = nlohmann::json::parse(ReadFile(report / "calibration.json"));
  EXPECT_EQ(j["robot"], "nao");
  EXPECT_EQ(j["trials_per_kick"], 40);
  ASSERT_EQ(j["kicks"].size(), 1u);
  EXPECT_EQ(j["kicks"][0]["name"], "side_kick_left");
  EXPECT_EQ(j["kicks"][0]["observations"].get<int>() + j["kicks"][0]["missed"].get<int>(), 40);
  // Trials whose placement put the ball inside the robot and were drawn again (about 1 % for
  // the side kick): counted, never more than the trials.
  EXPECT_GE(j["kicks"][0]["placement_redrawn"].get<int>(), 0);
  EXPECT_LE(j["kicks"][0]["placement_redrawn"].get<int>(), 40);
  const std::string kicks_csv = ReadFile(report / "calibration_kicks.csv");
  EXPECT_EQ(CountOf(kicks_csv, "\n"), 41) << kicks_csv.substr(0, 300);
  EXPECT_THAT(kicks_csv, StartsWith("kick,"));
  EXPECT_EQ(CountOf(kicks_csv, "\nside_kick_left,"), 40);
  const std::string summary = ReadFile(report / "calibration_summary.csv");
  EXPECT_EQ(CountOf(summary, "\n"), 2) << summary;
  EXPECT_THAT(summary, HasSubstr("\nside_kick_left,"));
  const std::string html = ReadFile(report / "calibration.html");
  EXPECT_THAT(html, HasSubstr("<svg"));
  EXPECT_THAT(html, ::testing::Not(HasSubstr("<script")));
  // What the run used: the committed model with its content hash, the real physics file, the
  // field; the launch offset the model gets, in the JSON and on the page.
  EXPECT_EQ(j["files"]["base_kicks"], "kicks/nao.json");
  EXPECT_THAT(j["files"]["base_kicks_hash"].get<std::string>(), StartsWith("fnv1a64:"));
  EXPECT_EQ(j["files"]["base_kicks_hash"].get<std::string>().size(), 8u + 16u);
  EXPECT_EQ(j["files"]["physics"], "physics/spl.json");
  EXPECT_EQ(j["files"]["field"], "spl");
  EXPECT_TRUE(j["kicks"][0]["launch_offset"].is_object());
  EXPECT_THAT(html, HasSubstr("launch offset (m)"));
  EXPECT_THAT(html, HasSubstr("written to the model"));
  EXPECT_THAT(html, HasSubstr(j["files"]["base_kicks_hash"].get<std::string>()));
}

TEST_F(CalibrateCommandTest, SameBytesWithOneThreadOrTwo) {
  const RunResult one = Calibrate(SideKick("1"));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const std::string model_one = ReadFile(work() / "fitted.json");
  nlohmann::json json_one = nlohmann::json::parse(ReadFile(work() / "report" / "calibration.json"));
  const std::string csv_one = ReadFile(work() / "report" / "calibration_kicks.csv");
  const RunResult two = Calibrate(SideKick("2"));
  ASSERT_EQ(two.exit_code, 0) << two.err;
  nlohmann::json json_two = nlohmann::json::parse(ReadFile(work() / "report" / "calibration.json"));
  EXPECT_FALSE(model_one.empty());
  EXPECT_EQ(model_one, ReadFile(work() / "fitted.json"));
  EXPECT_EQ(csv_one, ReadFile(work() / "report" / "calibration_kicks.csv"));
  ASSERT_TRUE(json_one.contains("run_time_s"));
  json_one.erase("run_time_s");
  json_two.erase("run_time_s");
  EXPECT_EQ(json_one, json_two);

  // A different seed draws different trials.
  std::vector<std::string> other = SideKick("2");
  other[7] = "4";
  ASSERT_EQ(other[6], "--seed");
  ASSERT_EQ(Calibrate(other).exit_code, 0);
  EXPECT_NE(model_one, ReadFile(work() / "fitted.json"));
}

TEST_F(CalibrateCommandTest, OneKickAloneFitsAsInAllKicks) {
  ASSERT_EQ(Calibrate(SideKick("2")).exit_code, 0);
  const nlohmann::json alone =
      nlohmann::json::parse(ReadFile(work() / "report" / "calibration.json"));
  const RunResult r = Calibrate({"--robot", "nao", "--all", "--trials", "40", "--seed", "3",
                                 "--out", "all.json", "--report", "all_report", "--base", "fixed"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json all =
      nlohmann::json::parse(ReadFile(work() / "all_report" / "calibration.json"));
  ASSERT_EQ(all["kicks"].size(), 3u);
  bool found = false;
  for (const nlohmann::json& kick : all["kicks"]) {
    if (kick["name"] != "side_kick_left") continue;
    found = true;
    EXPECT_EQ(kick["speed"], alone["kicks"][0]["speed"]);
    EXPECT_EQ(kick["direction"], alone["kicks"][0]["direction"]);
  }
  EXPECT_TRUE(found);
  EXPECT_EQ(CountOf(ReadFile(work() / "all_report" / "calibration_kicks.csv"), "\n"), 1 + 3 * 40);
}

TEST_F(CalibrateCommandTest, FromCsvFitsObservedKicks) {
  // 12 side kicks: speeds symmetric around 0.6, directions 90 +- d in pairs; every rest at
  // d = v0^2 / (2 * 0.3) straight along the launch (the robot faces +x from the origin).
  const double speeds[] = {0.50, 0.70, 0.55, 0.65, 0.58, 0.62, 0.52, 0.68, 0.60, 0.60, 0.57, 0.63};
  const double offsets[] = {0, 0, 2, -2, 4, -4, 6, -6, 1, -1, 3, -3};
  std::string csv =
      "kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,ball_y_m,launch_speed_mps,"
      "launch_direction_deg,rest_x_m,rest_y_m\n";
  for (int i = 0; i < 12; ++i) {
    const double direction = (90.0 + offsets[i]) * foresight::kDegToRad;
    const double d = speeds[i] * speeds[i] / (2.0 * 0.3);
    csv += "side_kick_left,0,0,0,0,0," + std::to_string(speeds[i]) + "," +
           std::to_string(90.0 + offsets[i]) + "," + std::to_string(d * std::cos(direction)) + "," +
           std::to_string(d * std::sin(direction)) + "\n";
  }
  Write("kicks.csv", csv);
  const RunResult r = Calibrate({"--robot", "nao", "--from-csv", "kicks.csv", "--out", "model.json",
                                 "--report", "csv_report"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("model.json"));
  const KickModel base = ShippedNao();
  const KickModel fitted = LoadKickModel(work() / "model.json");
  const KickSpec& left = fitted.kicks[*fitted.Find("side_kick_left")];
  EXPECT_NEAR(left.speed_mps, 0.6, 1e-4);
  EXPECT_NEAR(left.direction_rad, 90.0 * foresight::kDegToRad, 0.01 * foresight::kDegToRad);
  EXPECT_GT(left.sigma_speed_mps, 0.04);
  EXPECT_LT(left.sigma_speed_mps, 0.07);
  EXPECT_NEAR(fitted.rolling_deceleration_mps2, 0.3, 2e-4);  // from the roll distances
  const KickSpec& forward = fitted.kicks[*fitted.Find("forward")];
  EXPECT_NEAR(forward.speed_mps, base.kicks[*base.Find("forward")].speed_mps, 1e-12);
  const nlohmann::json j =
      nlohmann::json::parse(ReadFile(work() / "csv_report" / "calibration.json"));
  EXPECT_EQ(j["kicks"][0]["observations"], 12);
  EXPECT_EQ(CountOf(ReadFile(work() / "csv_report" / "calibration_kicks.csv"), "\n"), 13);
}

// A log whose rest-only rows roll at 0.3 m/s^2 (the rows with both a launch and a rest say so):
// their speeds come from the fitted deceleration, not from the committed model's 0.27.
TEST_F(CalibrateCommandTest, FromCsvRestOnlyRowsUseTheFittedDeceleration) {
  std::string csv =
      "kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,ball_y_m,launch_speed_mps,"
      "launch_direction_deg,rest_x_m,rest_y_m\n";
  const double speeds[] = {0.9, 1.1, 0.95, 1.05, 1.0, 1.0, 0.92, 1.08, 0.97, 1.03};
  for (int i = 0; i < 10; ++i) {
    const double d = speeds[i] * speeds[i] / (2.0 * 0.3);
    const double alpha_deg = (i % 2 ? 1.0 : -1.0) * 0.5 * (i + 1);
    const double alpha = alpha_deg * foresight::kDegToRad;
    const bool launch = i < 4;  // four rows with both, six with the rest only
    csv += "forward,0,0,0,0,0," +
           (launch ? std::to_string(speeds[i]) + "," + std::to_string(alpha_deg)
                   : std::string(",")) +
           "," + std::to_string(d * std::cos(alpha)) + "," + std::to_string(d * std::sin(alpha)) +
           "\n";
  }
  Write("rest_only.csv", csv);
  const RunResult r = Calibrate({"--robot", "nao", "--from-csv", "rest_only.csv", "--kick",
                                 "forward", "--out", "model.json", "--report", "rest_report"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const KickModel fitted = LoadKickModel(work() / "model.json");
  EXPECT_NEAR(fitted.rolling_deceleration_mps2, 0.3, 2e-4);
  // Mean of the ten speeds is 1.0; with the committed 0.2697 it would be 0.948.
  EXPECT_NEAR(fitted.kicks[*fitted.Find("forward")].speed_mps, 1.0, 1e-3);
  EXPECT_THAT(r.out, HasSubstr("with the fitted deceleration 0.3000"));
}

// A side kick logged in radians: refused, naming the file and the row.
TEST_F(CalibrateCommandTest, FromCsvRadiansAreRefusedNamingTheRow) {
  std::string csv =
      "kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,ball_y_m,launch_speed_mps,"
      "launch_direction_deg,rest_x_m,rest_y_m\n";
  for (int i = 0; i < 10; ++i) {
    const double alpha = (88.0 + 0.5 * i) * foresight::kDegToRad;
    csv += "side_kick_left,0,0,0,0,0,0.7," + std::to_string(alpha) + "," +
           std::to_string(0.8 * std::cos(alpha)) + "," + std::to_string(0.8 * std::sin(alpha)) +
           "\n";
  }
  Write("radians.csv", csv);
  const RunResult r = Calibrate({"--robot", "nao", "--from-csv", "radians.csv", "--out",
                                 "model.json", "--report", "radian_report"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, StartsWith("foresight: error: radians.csv: line 2: launch_direction_deg: "));
  EXPECT_THAT(r.err, HasSubstr("looks like radians"));
  EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
  EXPECT_FALSE(fs::exists(work() / "model.json"));
  EXPECT_FALSE(fs::exists(work() / "radian_report"));
}

// The example log shipped in models/logs/ (made from physics trials) calibrates as the docs say.
TEST_F(CalibrateCommandTest, ShippedExampleLogCalibrates) {
  const fs::path log =
      fs::path(FORESIGHT_TEST_MODELS_DIR) / "logs" / "nao_kicks_example.csv";
  const RunResult r = Calibrate({"--robot", "nao", "--all", "--from-csv", log.string(), "--out",
                                 "example.json", "--report", "example_report"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const KickModel fitted = LoadKickModel(work() / "example.json");
  const KickModel base = ShippedNao();
  for (const KickSpec& k : fitted.kicks) {
    const KickSpec& was = base.kicks[*base.Find(k.name)];
    EXPECT_NE(k.speed_mps, was.speed_mps) << k.name;  // every kick is in the log
    // Physics kicks go where the model says, within its sigma.
    EXPECT_NEAR(k.direction_rad, was.direction_rad, was.sigma_direction_rad) << k.name;
  }
  EXPECT_TRUE(fs::exists(work() / "example_report" / "calibration.html"));
}

// --fit-variation reads a log's spreads and writes the fitted causes as robot.json's block.
TEST_F(CalibrateCommandTest, FitVariationWritesTheFittedTrialVariation) {
  std::string csv = "kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,ball_y_m,launch_speed_mps,"
                    "launch_direction_deg\n";
  for (int i = 0; i < 40; ++i) {  // speeds 0.70..0.80, directions -4..+4 deg
    csv += "forward,0,0,0,0.18,-0.05," + std::to_string(0.70 + 0.1 * (i % 10) / 9.0) + "," +
           std::to_string(-4.0 + 8.0 * (i % 8) / 7.0) + "\n";
  }
  Write("log.csv", csv);
  // The fixed base, the cheap approximation: the fit's three physics runs of 60 trials.
  const RunResult r = Calibrate({"--robot", "nao", "--from-csv", "log.csv", "--fit-variation",
                                 "--fit-trials", "60", "--threads", "2", "--base", "fixed",
                                 "--out", "var.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("physics, fitted"));
  const nlohmann::json j = nlohmann::json::parse(ReadFile(work() / "var.json"));
  EXPECT_EQ(j["robot"], "nao");
  EXPECT_GT(j["trial_variation"]["placement_sigma_x_m"].get<double>(), 0.0);
  EXPECT_EQ(j["fit"]["kicks"][0]["kick"], "forward");
  EXPECT_TRUE(j["fit"].contains("rms_residual_rel"));
  EXPECT_THAT(r.out, HasSubstr("calibrate --variation var.json"));

  // The file is the variation that physics calibration and simulate then play, no hand copy.
  const RunResult physics = Calibrate({"--robot", "nao", "--kick", "forward", "--trials", "8",
                                       "--variation", "var.json", "--out", "with_var.json",
                                       "--report", "var_report"});
  ASSERT_EQ(physics.exit_code, 0) << physics.err;
  const nlohmann::json report =
      nlohmann::json::parse(ReadFile(work() / "var_report" / "calibration.json"));
  EXPECT_EQ(report["files"]["variation"], "var.json");
  const RunResult simulate =
      Run({"simulate", "--situation", foresight::testing::ShippedSituation("open_goal").string(),
           "--kick", "forward", "--trials", "2", "--variation", "var.json", "--json"});
  ASSERT_EQ(simulate.exit_code, 0) << simulate.err;
  EXPECT_EQ(nlohmann::json::parse(simulate.out)["situation"]["trial_variation"], "var.json");
  // A variation of another robot is refused.
  nlohmann::json other = j;
  other["robot"] = "aibo_ers7";
  Write("aibo_var.json", other.dump());
  const RunResult wrong = Calibrate({"--robot", "nao", "--kick", "forward", "--trials", "8",
                                     "--variation", "aibo_var.json", "--out", "x.json"});
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_THAT(wrong.err, HasSubstr("aibo_var.json: robot: the variation is for 'aibo_ers7'"));
}

TEST_F(CalibrateCommandTest, FitVariationNeedsALog) {
  const RunResult r = Calibrate({"--robot", "nao", "--fit-variation", "--out", "var.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, StartsWith("foresight: error: --fit-variation: needs --from-csv LOG"));
  EXPECT_FALSE(std::filesystem::exists(work() / "var.json"));
}

// The report folder is replaced whole (report/report_folder.h): a kick model written into it is
// one of its files, not a stranger that makes the folder irreplaceable, also on a second run.
TEST_F(CalibrateCommandTest, ModelInsideTheReportFolderIsPartOfIt) {
  std::vector<std::string> args = {"--robot",  "nao",    "--kick",      "forward",
                                   "--trials", "8",      "--out",       "report/model.json",
                                   "--report", "report", "--resamples", "100"};
  const RunResult first = Calibrate(args);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const RunResult again = Calibrate(args);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(fs::exists(work() / "report" / "model.json"));
  EXPECT_TRUE(fs::exists(work() / "report" / "calibration.html"));
  EXPECT_EQ(ReadFile(work() / "report" / "model.json").empty(), false);
}

TEST_F(CalibrateCommandTest, UnwritableModelLeavesNoReportBehind) {
  const RunResult r = Calibrate({"--robot", "nao", "--kick", "forward", "--trials", "10", "--out",
                                 "no_such_folder/model.json", "--report", "report"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, StartsWith("foresight: error: --out: no_such_folder/model.json"));
  EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(work() / "report"));
}

struct BadCalibrate {
  std::string name;
  std::vector<std::string> args;  // besides --out model.json --report report
  std::string message;
};

void PrintTo(const BadCalibrate& c, std::ostream* os) {
  *os << c.name;
}

class CalibrateErrorTest : public CalibrateCommandTest,
                           public ::testing::WithParamInterface<BadCalibrate> {};

TEST_P(CalibrateErrorTest, OneLineExitTwoNothingWritten) {
  Write("bad.csv",
        "kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,ball_y_m,launch_speed_mps,launch_"
        "direction_deg\n"
        "forward,0,0,0,0.15,0,1.0,0\n"
        "forward,0,0,0,0.15,0,fast,0\n");
  Write("short.csv",
        "kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,ball_y_m,launch_speed_mps,launch_"
        "direction_deg\n"
        "forward,0,0,0,0.15,0,1.0,0\n");
  Write("bicycle.csv",
        "kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,ball_y_m,rest_x_m,rest_y_m\n"
        "bicycle,0,0,0,0.15,0,-1,0\n");
  std::vector<std::string> args = GetParam().args;
  args.insert(args.end(), {"--out", "model.json", "--report", "report"});
  const std::set<std::string> before = Listing();
  const RunResult r = Calibrate(args);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_EQ(r.out, "");
  EXPECT_THAT(r.err, StartsWith("foresight: error: "));
  EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr(GetParam().message));
  EXPECT_FALSE(fs::exists(work() / "model.json"));
  EXPECT_FALSE(fs::exists(work() / "report"));
  EXPECT_EQ(Listing(), before);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CalibrateErrorTest,
    ::testing::Values(
        BadCalibrate{
            "UnknownRobot", {"--robot", "robocup_bot", "--kick", "forward"}, "robocup_bot"},
        BadCalibrate{"UnknownKick", {"--robot", "nao", "--kick", "bicycle"}, "bicycle"},
        BadCalibrate{
            "ThreeTrials", {"--robot", "nao", "--kick", "forward", "--trials", "3"}, "--trials"},
        BadCalibrate{"MissingCsv", {"--robot", "nao", "--from-csv", "absent.csv"}, "absent.csv"},
        BadCalibrate{"BadCsvCell", {"--robot", "nao", "--from-csv", "bad.csv"}, "line 3"},
        BadCalibrate{"TooFewCsvKicks",
                     {"--robot", "nao", "--from-csv", "short.csv"},
                     "error: short.csv: kick 'forward': 1 observed kicks, at least"},
        BadCalibrate{"CsvKickNotInModel",
                     {"--robot", "nao", "--from-csv", "bicycle.csv"},
                     "'bicycle' is not a kick"},
        BadCalibrate{"NoKickNorAll", {"--robot", "nao"}, "--kick"},
        BadCalibrate{"KicksOfAnotherRobot",
                     {"--robot", "nao", "--all", "--kicks",
                      FORESIGHT_TEST_MODELS_DIR "/kicks/aibo_ers7.json"},
                     "not --robot 'nao'"},
        BadCalibrate{"LowConfidence",
                     {"--robot", "nao", "--kick", "forward", "--confidence", "0.1"},
                     "--confidence"}),
    [](const ::testing::TestParamInfo<BadCalibrate>& info) { return info.param.name; });

}  // namespace
