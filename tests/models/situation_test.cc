#include "models/situation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/geometry.h"
#include "models/physics_params.h"
#include "tests/support/model_test_util.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

using testing::BrokenShipped;
using ::testing::HasSubstr;
using testing::InputErrorMessage;
using testing::ModelsDir;
using testing::ReplaceOnce;
using testing::ShippedText;
using ::testing::StartsWith;
using testing::WriteTempFile;

std::filesystem::path Shipped(const std::string& name) {
  return ModelsDir() / "situations" / (name + ".json");
}

// The shipped open_goal situation with `from` replaced by `to`, in a temporary file.
std::filesystem::path BrokenOpenGoal(const std::string& name, const std::string& from,
                                     const std::string& to) {
  return BrokenShipped("situations/open_goal.json", "situation_" + name, from, to);
}

std::string LoadError(const std::filesystem::path& file, const SituationOverrides& overrides = {}) {
  return InputErrorMessage([&] { LoadSituation(file, ModelsDir(), overrides); });
}

TEST(SituationTest, OpenGoalLoadsStateAndUncertainty) {
  const Situation s = LoadSituation(Shipped("open_goal"), ModelsDir());
  EXPECT_EQ(s.name, "open_goal");
  EXPECT_DOUBLE_EQ(s.state.robot.p_F.x(), 2.5);
  EXPECT_DOUBLE_EQ(s.state.robot.p_F.y(), 0.0);
  EXPECT_DOUBLE_EQ(s.state.robot.theta_rad, 0.0);
  EXPECT_DOUBLE_EQ(s.state.sigma_robot_x_m, 0.1);
  EXPECT_DOUBLE_EQ(s.state.sigma_robot_y_m, 0.1);
  EXPECT_NEAR(s.state.sigma_robot_theta_rad, 5.0 * kDegToRad, 1e-15);
  EXPECT_DOUBLE_EQ(s.state.p_R_ball.x(), 0.15);
  EXPECT_DOUBLE_EQ(s.state.sigma_ball_x_m, 0.05);
  EXPECT_DOUBLE_EQ(s.state.sigma_ball_y_m, 0.05);
  EXPECT_NEAR(s.state.MeanBallInField().x(), 2.65, 1e-12);
  EXPECT_TRUE(s.obstacles.empty());
}

TEST(SituationTest, BareNamesResolveToTheModelsFolder) {
  const Situation s = LoadSituation(Shipped("open_goal"), ModelsDir());
  EXPECT_EQ(s.field_file, ModelsDir() / "fields" / "spl.json");
  EXPECT_EQ(s.kicks_file, ModelsDir() / "kicks" / "nao.json");
  // Without an "evaluation" key the evaluation is the one named like the field.
  EXPECT_EQ(s.evaluation_file, ModelsDir() / "evaluation" / "spl.json");
  EXPECT_DOUBLE_EQ(s.field.field_length_m, 9.0);
  EXPECT_EQ(s.kicks.kicks.size(), 3u);
  EXPECT_EQ(s.evaluation.samples, 30);
}

TEST(SituationTest, AiboSituationUsesTheFourLeggedFieldAndEvaluation) {
  const Situation s = LoadSituation(Shipped("aibo_midfield"), ModelsDir());
  EXPECT_DOUBLE_EQ(s.field.field_length_m, 5.4);
  EXPECT_DOUBLE_EQ(s.field.field_width_m, 3.6);
  EXPECT_EQ(s.evaluation.name, "four_legged");
  EXPECT_NEAR(s.state.robot.theta_rad, 30.0 * kDegToRad, 1e-15);
}

TEST(SituationTest, ObstaclesAreRead) {
  const Situation s = LoadSituation(Shipped("blocked_by_defender"), ModelsDir());
  ASSERT_EQ(s.obstacles.size(), 2u);
  EXPECT_DOUBLE_EQ(s.obstacles[0].p_F.x(), 3.7);
  EXPECT_DOUBLE_EQ(s.obstacles[0].p_F.y(), -0.3);
  EXPECT_DOUBLE_EQ(s.obstacles[1].radius_m, 0.15);
}

TEST(SituationTest, ObstacleWithoutRadiusTakesTheFieldsDefault) {
  const auto file =
      BrokenOpenGoal("obstacle_default", "\"ball\": {",
                     "\"obstacles\": [{\"x_m\": -1.0, \"y_m\": 1.0}],\n  \"ball\": {");
  const Situation s = LoadSituation(file, ModelsDir());
  ASSERT_EQ(s.obstacles.size(), 1u);
  EXPECT_DOUBLE_EQ(s.obstacles[0].radius_m, 0.15);  // spl.json's default_obstacle_radius_m
}

TEST(SituationTest, EveryShippedSituationLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(ModelsDir() / "situations")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(LoadSituation(entry.path(), ModelsDir()));
    ++count;
  }
  EXPECT_GE(count, 6);
}

TEST(SituationTest, KicksOverrideReplacesTheSituationsModel) {
  const auto kicks = WriteTempFile("situation_override_kicks.json",
                                   R"({"robot": "test", "rolling_deceleration_mps2": 0.3,
          "kicks": [{"name": "chip", "speed_mps": 2.0, "sigma_speed_mps": 0.1,
                     "direction_deg": 0.0, "sigma_direction_deg": 2.0}]})");
  SituationOverrides overrides;
  overrides.kicks_file = kicks;
  const Situation s = LoadSituation(Shipped("open_goal"), ModelsDir(), overrides);
  EXPECT_EQ(s.kicks_file, kicks);
  ASSERT_EQ(s.kicks.kicks.size(), 1u);
  EXPECT_EQ(s.kicks.kicks[0].name, "chip");
}

TEST(SituationTest, CoarseReboundsReadTheirRestitutionFromThePhysicsFile) {
  SituationOverrides overrides;
  const Situation off = LoadSituation(Shipped("open_goal"), ModelsDir(), overrides);
  EXPECT_FALSE(off.evaluation.rebounds.enabled);
  overrides.coarse_rebounds = true;
  const Situation on = LoadSituation(Shipped("open_goal"), ModelsDir(), overrides);
  const BallPairs e = LoadPhysicsParams(ModelsDir() / "physics" / "spl.json").materials.restitution;
  EXPECT_TRUE(on.evaluation.rebounds.enabled);
  EXPECT_EQ(on.evaluation.rebounds.post, e.post);
  EXPECT_EQ(on.evaluation.rebounds.net, e.net);
  EXPECT_EQ(on.evaluation.rebounds.robot, e.robot);
  // Another physics file (a run's --physics) is the one read.
  overrides.physics_file = WriteTempFile(
      "situation_rebound_physics.json",
      ReplaceOnce(ShippedText("physics/spl.json"), "\"ball_post\": 0.3", "\"ball_post\": 0.5"));
  EXPECT_EQ(LoadSituation(Shipped("open_goal"), ModelsDir(), overrides).evaluation.rebounds.post,
            0.5);
}

TEST(SituationTest, CoarseReboundsWithoutAPhysicsFileNameIt) {
  SituationOverrides overrides;
  overrides.coarse_rebounds = true;
  overrides.physics_file = ModelsDir() / "physics" / "no_such_field.json";
  EXPECT_THAT(InputErrorMessage([&] { LoadSituation(Shipped("open_goal"), ModelsDir(), overrides); }),
              HasSubstr("rebounds.enabled: the coarse rebounds read their restitution from " +
                        overrides.physics_file.string() + ", which does not exist"));
}

TEST(SituationTest, BallOutsideTheCarpetNamesFilePositionAndCarpet) {
  // Robot on the carpet at x = 5.1, ball 0.15 m ahead: x = 5.25 > 5.2.
  const auto file = BrokenOpenGoal("ball_off_carpet", "\"x_m\": 2.5", "\"x_m\": 5.1");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": ball: position (5.25, 0)"));
  EXPECT_THAT(message, HasSubstr("outside the carpet"));
  EXPECT_THAT(message, HasSubstr("|x| <= 5.2 m, |y| <= 3.7 m"));
}

TEST(SituationTest, RobotOutsideTheCarpetIsRejected) {
  const auto file = BrokenOpenGoal("robot_off_carpet", "\"y_m\": 0.0, \"theta_deg\"",
                                   "\"y_m\": -4.0, \"theta_deg\"");
  EXPECT_THAT(LoadError(file),
              StartsWith(file.string() + ": robot: position (2.5, -4) is outside"));
}

TEST(SituationTest, ObstacleOverlappingTheBallIsRejected) {
  // The ball is at (2.65, 0); an obstacle of radius 0.15 at (2.75, 0) covers it.
  const auto file =
      BrokenOpenGoal("obstacle_on_ball", "\"ball\": {",
                     "\"obstacles\": [{\"x_m\": 2.75, \"y_m\": 0.0}],\n  \"ball\": {");
  EXPECT_EQ(LoadError(file), file.string() + ": obstacles[0]: overlaps the ball at (2.65, 0)");
}

// Issue 16: what physics cannot start from is bad input, named with the position.
TEST(SituationTest, BallInAPostIsRejected) {
  // Robot at (4.315, 0.8) facing +x, just clear of the post: the ball 0.15 m ahead lies 6 cm
  // from the post's centre, closer than the two radii (0.1 m).
  const auto file = BrokenOpenGoal("ball_in_post", "\"x_m\": 2.5, \"y_m\": 0.0",
                                   "\"x_m\": 4.315, \"y_m\": 0.8");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": ball: position (4.46"));
  EXPECT_THAT(message, HasSubstr("overlaps the goal post at (4.525, 0.8)"));
}

TEST(SituationTest, BallInsideTheGoalIsRejected) {
  const auto file = BrokenOpenGoal("ball_in_goal", "\"x_m\": 2.5", "\"x_m\": 4.5");
  EXPECT_EQ(LoadError(file), file.string() + ": ball: position (4.65, 0) lies inside a goal");
}

TEST(SituationTest, BallInTheBackNetIsRejected) {
  // The back net's line is at x = 4.525 + 0.5; the ball at 5.04 overlaps it.
  const auto file = BrokenOpenGoal("ball_in_net", "\"x_m\": 2.5", "\"x_m\": 4.89");
  EXPECT_EQ(LoadError(file), file.string() + ": ball: position (5.04, 0) overlaps a goal's net");
}

TEST(SituationTest, RobotStandingInAPostIsRejected) {
  const auto file = BrokenOpenGoal("robot_in_post", "\"x_m\": 2.5, \"y_m\": 0.0",
                                   "\"x_m\": 4.45, \"y_m\": -0.75");
  EXPECT_THAT(LoadError(file), StartsWith(file.string() + ": robot: position (4.45, -0.75) "
                                                          "overlaps the goal post at (4.525, -0.8)"));
}

TEST(SituationTest, ObstacleInAPostIsRejected) {
  const auto file =
      BrokenOpenGoal("obstacle_in_post", "\"ball\": {",
                     "\"obstacles\": [{\"x_m\": -4.5, \"y_m\": 0.8}],\n  \"ball\": {");
  EXPECT_EQ(LoadError(file),
            file.string() + ": obstacles[0]: position (-4.5, 0.8) overlaps the goal post at "
                            "(-4.525, 0.8)");
}

TEST(SituationTest, FieldThatDoesNotExistIsReportedAgainstTheFieldKey) {
  const auto file = BrokenOpenGoal("no_field", "\"field\": \"spl\"", "\"field\": \"spl_2030\"");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": field: refers to "));
  EXPECT_THAT(message, HasSubstr((ModelsDir() / "fields" / "spl_2030.json").string()));
  EXPECT_THAT(message, HasSubstr("does not exist"));
}

TEST(SituationTest, MissingOverrideKicksFileIsNamed) {
  SituationOverrides overrides;
  overrides.kicks_file = "/nonexistent/kicks.json";
  const std::string message = LoadError(Shipped("open_goal"), overrides);
  EXPECT_THAT(message, HasSubstr("/nonexistent/kicks.json"));
  EXPECT_THAT(message, HasSubstr("does not exist"));
}

TEST(SituationTest, NegativeRobotSigmaNamesFieldAndValue) {
  const auto file = BrokenOpenGoal("negative_sigma", "\"sigma_x_m\": 0.1", "\"sigma_x_m\": -0.1");
  EXPECT_EQ(LoadError(file), file.string() + ": robot.sigma_x_m: must be >= 0, got -0.1");
}

TEST(SituationTest, NegativeBallSigmaNamesFieldAndValue) {
  const auto file =
      BrokenOpenGoal("negative_ball_sigma", "\"sigma_y_m\": 0.05", "\"sigma_y_m\": -0.05");
  EXPECT_EQ(LoadError(file), file.string() + ": ball.sigma_y_m: must be >= 0, got -0.05");
}

TEST(SituationTest, TypoInRobotKeyIsAnUnknownField) {
  const auto file = BrokenOpenGoal("typo", "\"theta_deg\"", "\"theta_dg\"");
  EXPECT_EQ(LoadError(file), file.string() + ": robot.theta_dg: unknown field");
}

TEST(SituationTest, PositionGivenAsStringNamesTheValue) {
  const auto file = BrokenOpenGoal("type", "\"x_m\": 2.5", "\"x_m\": \"2.5\"");
  EXPECT_EQ(LoadError(file), file.string() + ": robot.x_m: must be a number, got \"2.5\"");
}

TEST(SituationTest, FieldGivenAsPathWithExplicitEvaluationLoads) {
  WriteTempFile("situation_own_field.json", ShippedText("fields/spl.json"));
  const auto file =
      BrokenOpenGoal("field_path", "\"field\": \"spl\"",
                     "\"field\": \"situation_own_field.json\", \"evaluation\": \"spl\"");
  const Situation s = LoadSituation(file, ModelsDir());
  EXPECT_EQ(s.field_file, file.parent_path() / "situation_own_field.json");
  EXPECT_EQ(s.evaluation.name, "spl");
}

TEST(SituationTest, FieldGivenAsPathDoesNotReadTheFieldFileAsEvaluation) {
  // Without an "evaluation" key the evaluation shipped for the field's name applies, also when
  // the field is given as a path (it once loaded the field file as the evaluation).
  WriteTempFile("situation_own_field2.json", ShippedText("fields/spl.json"));
  const auto file = BrokenOpenGoal("field_path_no_eval", "\"field\": \"spl\"",
                                   "\"field\": \"situation_own_field2.json\"");
  const Situation s = LoadSituation(file, ModelsDir());
  EXPECT_EQ(s.evaluation.name, "spl");
  EXPECT_EQ(s.evaluation_file, ModelsDir() / "evaluation" / "spl.json");
}

TEST(SituationTest, InfiniteCoordinateCannotEnter) {
  // nlohmann rejects 1e999 with json::out_of_range; the reader wraps it with line and key.
  const auto file = BrokenOpenGoal("infinite_x", "\"x_m\": 2.5", "\"x_m\": 1e999");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, HasSubstr(file.string()));
  EXPECT_THAT(message, HasSubstr("line 6"));
  EXPECT_THAT(message, HasSubstr("field \"x_m\""));
  EXPECT_THAT(message, HasSubstr("1e999"));
}

}  // namespace
}  // namespace foresight
