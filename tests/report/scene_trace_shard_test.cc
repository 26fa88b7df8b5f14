// Recorded viewer trials in a shard file (report/scene_trace_shard.h): a trace read back writes
// the same bytes as the trace it was written from (so a page made from merged shards is the
// unsharded run's page), and a trace no recorder can write is refused with its place.
#include "report/scene_trace_shard.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "common/error.h"
#include "report/scene_trace_json.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

// A kick's trace (two links, a frame with the robot and one without, an obstacle robot) and a
// match's (one body), with values that are not whole units.
ViewerTrial Recorded() {
  ViewerTrial trial;
  trial.label = "coarse choice: forward 30 deg, trial 0";
  trial.numbers = {{"launch speed", "1.234 m/s"}, {"strike", "1.180 s (the launching touch)"}};
  SceneTrace& t = trial.trace;
  t.rate_hz = 100.0;
  t.links = {"torso", "l_foot"};
  t.phases = {"kick", "roll"};
  t.bodies = {{"A", 0, 0.2, 0.58}};
  SceneFrame kick;
  kick.t_s = 0.0123456;
  kick.ball.p_F = {1.000049, -0.33333, 0.05};
  kick.ball.q_F =
      Eigen::Quaterniond(Eigen::AngleAxisd(-2.5, Eigen::Vector3d(1, 2, 3).normalized()));
  kick.w_F_ball = {0.123, -45.678, 0.0};
  kick.links = {
      {{0.1, 0.2, 0.3}, Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()))},
      {{-0.00004, 0.0, 0.04}, Eigen::Quaterniond::Identity()}};
  kick.bodies = {Pose2{Vec2(1.23456, -0.5), 3.1}};
  SceneFrame roll = kick;
  roll.t_s = 0.5;
  roll.phase = 1;
  roll.links.clear();
  t.frames = {kick, roll};
  t.contacts = {{0.0123456, "ball", "l_foot", {1.0, -0.3, 0.05}, 0.0456789}};
  t.obstacles = {kick.links};
  return trial;
}

// The refusal of reading `shard` after `edit` ("" if it reads).
std::string ReadEdited(const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json shard = ViewerTrialShardJson(Recorded());
  edit(shard);
  try {
    ReadShardViewerTrial(ShardValue(shard, "s/shard.json", "views[0]"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneTraceShardTest, ATraceReadBackWritesTheSameBytes) {
  const ViewerTrial trial = Recorded();
  const nlohmann::json shard = nlohmann::json::parse(ViewerTrialShardJson(trial).dump());
  const ViewerTrial again = ReadShardViewerTrial(ShardValue(shard, "s/shard.json", "views[0]"));
  EXPECT_EQ(again.label, trial.label);
  EXPECT_EQ(again.numbers, trial.numbers);
  EXPECT_EQ(SceneTraceJson(again.trace), SceneTraceJson(trial.trace));
  ASSERT_EQ(again.trace.frames.size(), 2u);
  EXPECT_TRUE(again.trace.frames[1].links.empty());
  EXPECT_NEAR(again.trace.frames[0].ball.p_F.x(), 1.000049, 0.5 / kTraceUnitsPerM);
}

TEST(SceneTraceShardTest, ATraceNoRecorderWritesIsRefusedWithItsPlace) {
  EXPECT_EQ(ReadEdited([](nlohmann::json&) {}), "");
  EXPECT_THAT(ReadEdited([](nlohmann::json& j) { j["trace"]["ball"][0][6] = -5000; }),
              HasSubstr("views[0].trace.ball[0][6]: "));
  EXPECT_THAT(ReadEdited([](nlohmann::json& j) { j["trace"]["links_pose"][0].erase(0); }),
              HasSubstr("views[0].trace.links_pose[0]: must hold 7 numbers per pose, 2"));
  EXPECT_THAT(ReadEdited([](nlohmann::json& j) { j["trace"]["t"][1] = 0; }),
              HasSubstr("views[0].trace.t[1]: must not decrease"));
  EXPECT_THAT(ReadEdited([](nlohmann::json& j) { j["trace"]["phase"].push_back(0); }),
              HasSubstr("views[0].trace.phase: must have one entry per time, 2"));
  EXPECT_THAT(ReadEdited([](nlohmann::json& j) { j["trace"]["units"]["m"] = 1000; }),
              HasSubstr("views[0].trace.units.m: must be "));
  EXPECT_THAT(ReadEdited([](nlohmann::json& j) { j["trace"]["contacts"][0][6] = -1; }),
              HasSubstr("views[0].trace.contacts[0][6]: must be 0 or more"));
  EXPECT_THAT(ReadEdited([](nlohmann::json& j) { j["numbers"][0] = {"x"}; }),
              HasSubstr("views[0].numbers[0]: must be [name, text]"));
}

}  // namespace
}  // namespace foresight
