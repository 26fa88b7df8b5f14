// The match's data files: the shipped ones load; a figure without a source, a bad value, a
// defender region reaching into the penalty area and an opponent starting outside its region
// are errors naming the file and the field.
#include "match/match_params.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <functional>

#include "common/error.h"
#include "match/match_config.h"
#include "match/reactive_team.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

std::string Shipped(const std::string& name) {
  return testing::ReadText(testing::ModelsDir() / "match" / name);
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string ErrorOf(const std::function<void()>& load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MatchParamsTest, ShippedFilesLoad) {
  const auto models = testing::ModelsDir();
  const RobotParams robot = LoadRobotParams("aibo_ers7", models);
  EXPECT_DOUBLE_EQ(robot.walk_speed_mps, 0.406);
  const SimulationParams sim = LoadSimulationParams("simulation", models);
  const FieldSpec field = LoadFieldSpec(models / "fields" / "four_legged.json");
  for (const char* config : {"dg", "2d"}) {
    const MatchConfig c = LoadMatchConfig(config, models, field, sim, robot);
    EXPECT_EQ(c.scenarios.size(), 4u) << config;
  }
  EXPECT_DOUBLE_EQ(LoadReactiveParams("reactive", models).dodge_radius_m, 0.4);
}

TEST(MatchParamsTest, EveryFigureNeedsASource) {
  const auto file = testing::WriteTempFile(
      "robot.json", Replace(Shipped("aibo_ers7.json"), "\"kick_launch_s\": \"assumption",
                            "\"kick_launch_x\": \"assumption"));
  const std::string error = ErrorOf([&] { LoadRobotParams(file.string(), "."); });
  EXPECT_THAT(error, HasSubstr(file.string() + ": sources"));
  EXPECT_THAT(error, HasSubstr("kick_launch_x"));
}

TEST(MatchParamsTest, BadValueNamesFileFieldAndValue) {
  const auto file = testing::WriteTempFile(
      "robot.json", Replace(Shipped("aibo_ers7.json"), "\"grab_failure_rate\": 0.2",
                            "\"grab_failure_rate\": 1.5"));
  const std::string error = ErrorOf([&] { LoadRobotParams(file.string(), "."); });
  EXPECT_THAT(error, HasSubstr(file.string() + ": grab_failure_rate"));
  EXPECT_THAT(error, HasSubstr("1.5"));
}

TEST(MatchParamsTest, ReactiveTeamNeedsARoleRegionPerAttacker) {
  const std::string text =
      Replace(Shipped("reactive.json"),
              ",\n    {\"x_min_m\": -2.7, \"x_max_m\": 2.7, \"y_min_m\": -1.8, "
              "\"y_max_m\": 0.6}",
              "");
  const auto file = testing::WriteTempFile("reactive.json", text);
  const std::string error = ErrorOf([&] { LoadReactiveParams(file.string(), "."); });
  EXPECT_THAT(error,
              HasSubstr(file.string() + ": role_regions: must give one region per attacker"));
}

TEST(MatchParamsTest, ContestClearanceIsCheckedAndNeedsASource) {
  const auto bad = testing::WriteTempFile(
      "sim.json", Replace(Shipped("simulation.json"), "\"contest_clearance_m\": 0.3",
                          "\"contest_clearance_m\": -0.3"));
  const std::string error = ErrorOf([&] { LoadSimulationParams(bad.string(), "."); });
  EXPECT_THAT(error, HasSubstr(bad.string() + ": contest_clearance_m"));
  EXPECT_THAT(error, HasSubstr("-0.3"));
  const auto unsourced = testing::WriteTempFile(
      "sim.json", Replace(Shipped("simulation.json"), "\"contest_clearance_m\": \"assumption",
                          "\"contest_clearance_x\": \"assumption"));
  const std::string unsourced_error = ErrorOf([&] { LoadSimulationParams(unsourced.string(), "."); });
  EXPECT_THAT(unsourced_error, HasSubstr(unsourced.string() + ": sources"));
  EXPECT_THAT(unsourced_error, HasSubstr("contest_clearance_x"));
}

TEST(MatchParamsTest, LocalGameStuckFiguresAreChecked) {
  const std::pair<const char*, const char*> cases[] = {
      {"\"stuck_after_s\": 10.0", "\"stuck_after_s\": 0"},
      {"\"stuck_penalty_s\": 45.0", "\"stuck_penalty_s\": -45"},
      {"\"stuck_proximity_m\": 0.5", "\"stuck_proximity_m\": 50"},
      {"\"stuck_ball_still_m\": 0.1", "\"stuck_ball_still_m\": -0.1"}};
  for (const auto& [from, to] : cases) {
    const auto bad = testing::WriteTempFile("sim.json", Replace(Shipped("simulation.json"), from, to));
    const std::string error = ErrorOf([&] { LoadSimulationParams(bad.string(), "."); });
    const std::string field = std::string(from).substr(1, std::string(from).find('"', 1) - 1);
    EXPECT_THAT(error, HasSubstr(bad.string() + ": " + field)) << to;
  }
}

TEST(MatchParamsTest, ReactiveRuleFiguresAreChecked) {
  const auto file = testing::WriteTempFile(
      "reactive.json",
      Replace(Shipped("reactive.json"), "\"regrab_delay_s\": 2.0", "\"regrab_delay_s\": -1"));
  const std::string error = ErrorOf([&] { LoadReactiveParams(file.string(), "."); });
  EXPECT_THAT(error, HasSubstr(file.string() + ": regrab_delay_s"));
  EXPECT_THAT(error, HasSubstr("-1"));
}

class ConfigTest : public ::testing::Test {
 protected:
  std::filesystem::path models_ = testing::ModelsDir();
  RobotParams robot_ = LoadRobotParams("aibo_ers7", models_);
  SimulationParams sim_ = LoadSimulationParams("simulation", models_);
  FieldSpec field_ = LoadFieldSpec(models_ / "fields" / "four_legged.json");
  std::string Load(const std::string& text) {
    // Bare scenario names resolve to the shipped scenarios.
    const auto dir = testing::WriteTempFile("scenarios_dummy", "").parent_path();
    return ErrorOf([&] {
      const auto file = dir / "config.json";
      std::ofstream(file) << text;
      LoadMatchConfig(file.string(), models_, field_, sim_, robot_);
    });
  }
  // Scenario dg_1 with `from` replaced by `to`, played in the DG configuration: the error.
  std::string ScenarioError(const std::string& from, const std::string& to) {
    const auto dir = testing::WriteTempFile("scenarios_dummy", "").parent_path();
    std::ofstream(dir / "tampered.json")
        << Replace(testing::ReadText(models_ / "match" / "scenarios" / "dg_1.json"), from, to);
    return Load(Replace(Shipped("dg.json"), "\"dg_1\"", "\"tampered.json\""));
  }
};

TEST_F(ConfigTest, DefenderRegionInThePenaltyAreaIsAnError) {
  const std::string error =
      Load(Replace(Shipped("dg.json"), "\"x_max_m\": 1.9", "\"x_max_m\": 2.0"));
  EXPECT_THAT(error, HasSubstr("opponents[0].region: a defender's body"));
}

TEST_F(ConfigTest, OpponentStartingOutsideItsRegionIsAnError) {
  const std::string error =
      Load(Replace(Shipped("dg.json"), "\"x_min_m\": -0.3", "\"x_min_m\": 0.5"));
  EXPECT_THAT(error, HasSubstr("opponent D starts outside its region"));
}

TEST_F(ConfigTest, TheGoalieModelIsThePapersByDefaultRunswiftsOnRequestAndNothingElse) {
  const MatchConfig dg = LoadMatchConfig("dg", models_, field_, sim_, robot_);
  EXPECT_EQ(dg.goalie.model, GoalieModel::kRos2009);
  EXPECT_EQ(Load(Replace(Shipped("dg.json"), "\"model\": \"ros2009\"",
                         "\"model\": \"runswift2005\"")),
            "no error");
  const std::string error =
      Load(Replace(Shipped("dg.json"), "\"model\": \"ros2009\"", "\"model\": \"keeper9\""));
  EXPECT_THAT(error, HasSubstr("config.json: goalie.model: must be ros2009 or runswift2005"));
  EXPECT_THAT(error, HasSubstr("keeper9"));
}

// A scenario's name goes into its output files' names: a slash, a control character or an empty
// name is refused with the file and field (they made a sub-folder, an escape sequence or
// "passing_example_.svg"), and so are two scenarios of one name.
TEST_F(ConfigTest, AScenarioNameThatCannotNameAFileIsAnError) {
  for (const std::string name : {"a/b", "x\\u001b[31m", ""}) {
    SCOPED_TRACE(name);
    const std::string error =
        ScenarioError("\"name\": \"dg_1\"", "\"name\": \"" + name + "\"");
    EXPECT_THAT(error, HasSubstr("tampered.json: name: must be 1-64 letters, digits, '_', '-' or "
                                 "'.' (it names the output files), got '"));
    EXPECT_EQ(error.find('\x1b'), std::string::npos);
  }
  const std::string twice = Load(Replace(Shipped("dg.json"), "\"dg_4\"", "\"dg_1\""));
  EXPECT_THAT(twice, HasSubstr("config.json: scenarios: scenarios[0] and scenarios[3] are both "
                               "named 'dg_1'"));
}

TEST_F(ConfigTest, UnknownScenarioNamesTheMissingFileAndTheFieldThatNamesIt) {
  const std::string error = Load(Replace(Shipped("dg.json"), "\"dg_4\"", "\"dg_9\""));
  EXPECT_THAT(error, HasSubstr("config.json: scenarios[3]: refers to "));
  EXPECT_THAT(error, HasSubstr("dg_9.json, which does not exist"));
}

TEST_F(ConfigTest, AScenarioAMatchCannotStartFromIsAnErrorNamingFileFieldAndValue) {
  const std::string file = (testing::WriteTempFile("scenarios_dummy", "").parent_path() /
                            "tampered.json").string();
  const std::string ball = "\"x_m\": -1.3,\n    \"y_m\": 0.0";
  const std::string a = "\"x_m\": -1.65,\n      \"y_m\": 0.0,\n      \"theta_deg\": 0";
  EXPECT_EQ(ScenarioError(ball, "\"x_m\": 100, \"y_m\": 0.0"),
            file + ": ball: (100, 0) is off the field (|x| <= 2.7 m, |y| <= 1.8 m)");
  const std::string far = ScenarioError(ball, "\"x_m\": 1e300, \"y_m\": 0.0");
  EXPECT_THAT(far, HasSubstr(file + ": ball: ("));
  EXPECT_THAT(far, HasSubstr("is off the field"));
  EXPECT_EQ(ScenarioError(a, "\"x_m\": -1.5, \"y_m\": -0.9, \"theta_deg\": 0"),
            file + ": attackers[1]: position (-1.5, -0.9) overlaps attackers[0] at (-1.5, -0.9) "
                   "(robots of radius 0.12 m)");
  EXPECT_THAT(ScenarioError(a, "\"x_m\": -0.35, \"y_m\": 0.05, \"theta_deg\": 0"),
              HasSubstr(file + ": opponents[0]: position (-0.3, 0) overlaps attackers[0]"));
  EXPECT_THAT(ScenarioError(a, "\"x_m\": -1.65, \"y_m\": 0.0, \"theta_deg\": 1e308"),
              HasSubstr(file + ": attackers[0].theta_deg: "));
  EXPECT_THAT(ScenarioError(a, "\"x_m\": -1.65, \"y_m\": 5.0, \"theta_deg\": 0"),
              HasSubstr(file + ": attackers[0]: (-1.65, 5) is off the field"));
  EXPECT_EQ(ScenarioError(ball, ball), "no error");  // the shipped scenario itself
}

}  // namespace
}  // namespace foresight
