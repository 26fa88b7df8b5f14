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
  EXPECT_DOUBLE_EQ(robot.walk_speed_mps, 0.3);
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
      "robot.json", Replace(Shipped("aibo_ers7.json"), "\"kick_time_s\": \"assumption",
                            "\"kick_time_x\": \"assumption"));
  const std::string error = ErrorOf([&] { LoadRobotParams(file.string(), "."); });
  EXPECT_THAT(error, HasSubstr(file.string() + ": sources"));
  EXPECT_THAT(error, HasSubstr("kick_time_x"));
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

TEST_F(ConfigTest, UnknownScenarioNamesTheMissingFile) {
  const std::string error = Load(Replace(Shipped("dg.json"), "\"dg_4\"", "\"dg_9\""));
  EXPECT_THAT(error, HasSubstr("dg_9.json"));
}

}  // namespace
}  // namespace foresight
