// Every figure of the match's data files (models/match/*.json; the scenarios hold positions)
// carries a source in the file's "sources" object, and every source names a figure of its
// file; the four motion figures and the grab are rUNSWift 2005's, recomputed here from the step
// sizes, periods and frame counts the sources quote (docs/sources/four_legged_figures.md sec. 3
// and 4).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "common/geometry.h"
#include "match/match_params.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

// Keys that name other files or describe the file, not figures.
const std::set<std::string> kNotFigures = {"name", "notes", "sources", "field", "kicks", "robot"};

TEST(MatchSourcesTest, EveryFigureOfEveryMatchFileHasASourceAndEverySourceAFigure) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(testing::ModelsDir() / "match")) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    std::ifstream in(entry.path());
    const nlohmann::json doc = nlohmann::json::parse(in);
    ASSERT_TRUE(doc.contains("sources")) << entry.path();
    const nlohmann::json& sources = doc["sources"];
    for (const auto& [key, value] : doc.items()) {
      if (kNotFigures.count(key) > 0) continue;
      ASSERT_TRUE(sources.contains(key)) << entry.path() << ": " << key << " has no source";
      const std::string text = sources[key].get<std::string>();
      EXPECT_GT(text.size(), 20u) << entry.path() << ": " << key << ": a source says where";
    }
    for (const auto& [key, value] : sources.items()) {
      EXPECT_TRUE(doc.contains(key)) << entry.path() << ": source for no figure: " << key;
    }
  }
  EXPECT_GE(files, 5);
}

TEST(MatchSourcesTest, MotionAndGrabFiguresAreRunswift2005s) {
  const RobotParams robot = LoadRobotParams("aibo_ers7", testing::ModelsDir());
  // robot/PyCode/Action.py: PG 22 steps of 0.352 s, the grab dribble's PG 18 of 0.288 s.
  EXPECT_NEAR(robot.walk_speed_mps, 0.1428 / 0.352, 0.0005);  // 14.28 cm per step forward
  // 74.5 deg per step counter-clockwise, 77.7 clockwise: the slower of the two.
  EXPECT_NEAR(robot.turn_speed_radps * kRadToDeg, std::min(74.5, 77.7) / 0.352, 0.5);
  EXPECT_NEAR(robot.walk_sideways_mps, std::min(0.07, 0.0686) / 0.352, 0.0005);  // left, right
  EXPECT_NEAR(robot.walk_backward_mps, 0.102 / 0.352, 0.005);
  EXPECT_NEAR(robot.dribble_speed_mps, 0.0957 / 0.288, 0.005);  // 9.57 cm per step
  EXPECT_NEAR(robot.dribble_sideways_mps, std::min(0.061, 0.0642) / 0.288, 0.005);
  EXPECT_EQ(robot.dribble_backward_mps, 0.0);
  EXPECT_NEAR(robot.dribble_turn_speed_radps * kRadToDeg, std::min(60.2, 63.8) / 0.288, 0.5);
  // robot/PyCode/sGrab.py: GRAB_COMPLETE_TIME 25 frames at 30 per second; GRAB_DIST 17 cm less
  // the 5.6 cm a ball against the chest is seen at; the ball's heading within 8 deg.
  EXPECT_NEAR(robot.grab_time_s, 25.0 / 30.0, 0.005);
  EXPECT_NEAR(robot.grab_reach_m, 0.17 - 0.056, 1e-9);
  EXPECT_NEAR(robot.grab_cone_rad * kRadToDeg, 8.0, 1e-9);
}

}  // namespace
}  // namespace foresight
