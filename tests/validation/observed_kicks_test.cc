// Reading a robot's real kicks from CSV: launches, rest positions (speed sqrt(2 a d), direction
// the bearing in the robot frame), both, empty optional cells, and one-line errors that say
// where.
#include "validation/observed_kicks.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "common/error.h"
#include "common/geometry.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr double kA = 0.27;  // assumed deceleration

// A CSV in the shared temporary folder, unique per test and process.
std::filesystem::path Csv(const std::string& name, const std::string& text) {
  return testing::WriteTempFile(
      "observed_kicks_test_" + name + "_" + std::to_string(::getpid()) + ".csv", text);
}

const std::string kPose = "kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,ball_y_m";

TEST(ObservedKicksTest, LaunchColumns) {
  const auto file = Csv("launch", kPose +
                                      ",launch_speed_mps,launch_direction_deg\n"
                                      "forward,0,0,0,0.15,0,1.05,-3\n"
                                      "side_kick_left,1,2,90,1,2.15,0.7,92.5\n"
                                      "\n"  // blank lines are skipped
                                      "forward, 0 ,0,0,0.15,0,1.10,4\r\n");
  const ObservedKicks k = ReadObservedKicks(file, kA);
  EXPECT_EQ(k.rows, 3);
  EXPECT_EQ(k.speeds_from_rest, 0);
  EXPECT_EQ(k.kick_names, (std::vector<std::string>{"forward", "side_kick_left"}));
  ASSERT_EQ(k.by_kick.at("forward").size(), 2u);
  ASSERT_EQ(k.by_kick.at("side_kick_left").size(), 1u);
  const KickObservation& first = k.by_kick.at("forward")[0];
  EXPECT_DOUBLE_EQ(first.launch_speed_mps, 1.05);
  EXPECT_NEAR(first.launch_direction_rad, -3.0 * kDegToRad, 1e-12);
  EXPECT_FALSE(first.has_roll_distance);
  EXPECT_TRUE(first.rolling.empty());
  EXPECT_DOUBLE_EQ(k.by_kick.at("forward")[1].launch_speed_mps, 1.10);
  EXPECT_NEAR(k.by_kick.at("forward")[1].launch_direction_rad, 4.0 * kDegToRad, 1e-12);
  // The launch direction is already in the robot frame: the robot's heading does not enter.
  EXPECT_NEAR(k.by_kick.at("side_kick_left")[0].launch_direction_rad, 92.5 * kDegToRad, 1e-12);
}

TEST(ObservedKicksTest, RestColumnsGiveSpeedAndBearingInTheRobotFrame) {
  // Robot 1: at (1, 2) facing +y; the ball rolls 1 m towards -x, i.e. to the robot's left.
  // Robot 2: facing -45 deg; the ball rolls (0.3, 0.4) = 0.5 m at atan2(0.4, 0.3) in F.
  // Robot 3: facing 170 deg; the ball rolls (-0.6, -0.8) = 1 m at -126.87 deg in F, which is
  //          63.13 deg in the robot frame after wrapping.
  const auto file = Csv("rest", kPose +
                                    ",rest_x_m,rest_y_m\n"
                                    "side_kick_left,1,2,90,1,2.15,0,2.15\n"
                                    "forward,-1,0,-45,0.5,0.5,0.8,0.9\n"
                                    "forward,0,0,170,0.1,0.2,-0.5,-0.6\n");
  const ObservedKicks k = ReadObservedKicks(file, kA);
  EXPECT_EQ(k.rows, 3);
  EXPECT_EQ(k.speeds_from_rest, 3);
  const KickObservation& left = k.by_kick.at("side_kick_left")[0];
  EXPECT_NEAR(left.launch_speed_mps, std::sqrt(2.0 * kA * 1.0), 1e-12);
  EXPECT_NEAR(left.launch_direction_rad, std::numbers::pi / 2.0, 1e-12);
  EXPECT_NEAR(left.roll_distance_m, 1.0, 1e-12);
  EXPECT_FALSE(left.has_roll_distance);  // a derived speed cannot fit the deceleration
  const KickObservation& second = k.by_kick.at("forward")[0];
  EXPECT_NEAR(second.launch_speed_mps, std::sqrt(2.0 * kA * 0.5), 1e-12);
  EXPECT_NEAR(second.launch_direction_rad, std::atan2(0.4, 0.3) + std::numbers::pi / 4.0, 1e-12);
  const KickObservation& third = k.by_kick.at("forward")[1];
  EXPECT_NEAR(third.launch_speed_mps, std::sqrt(2.0 * kA * 1.0), 1e-12);
  EXPECT_NEAR(third.launch_direction_rad,
              std::atan2(-0.8, -0.6) - 170.0 * kDegToRad + 2.0 * std::numbers::pi, 1e-12);
  // The assumed deceleration scales the speed.
  const ObservedKicks faster = ReadObservedKicks(file, 4.0 * kA);
  EXPECT_NEAR(faster.by_kick.at("side_kick_left")[0].launch_speed_mps, 2.0 * left.launch_speed_mps,
              1e-12);
}

TEST(ObservedKicksTest, BothLaunchAndRestGiveARollDistance) {
  const auto file = Csv("both",
                        "launch_speed_mps,rest_y_m,kick,ball_x_m,ball_y_m,robot_x_m,"
                        "robot_y_m,robot_theta_deg,launch_direction_deg,rest_x_m\n"
                        "0.9,4,forward,0,0,-0.15,0,30,10,3\n");
  const ObservedKicks k = ReadObservedKicks(file, kA);
  ASSERT_EQ(k.rows, 1);
  EXPECT_EQ(k.speeds_from_rest, 0);
  const KickObservation& o = k.by_kick.at("forward")[0];
  EXPECT_TRUE(o.has_roll_distance);
  EXPECT_NEAR(o.roll_distance_m, 5.0, 1e-12);
  EXPECT_DOUBLE_EQ(o.launch_speed_mps, 0.9);                     // the launch, not sqrt(2 a d)
  EXPECT_NEAR(o.launch_direction_rad, 10.0 * kDegToRad, 1e-12);  // not the rest's bearing
}

TEST(ObservedKicksTest, EmptyOptionalCells) {
  const std::string header = kPose + ",launch_speed_mps,launch_direction_deg,rest_x_m,rest_y_m\n";
  const auto file = Csv("optional", header +
                                        "forward,0,0,0,0,0,1.0,5,,\n"         // launch only
                                        "forward,0,0,0,0,0,,,2,0\n"           // rest only
                                        "forward,0,0,0,0,0,1.2,-5,2.5,0\n");  // both
  const ObservedKicks k = ReadObservedKicks(file, kA);
  ASSERT_EQ(k.rows, 3);
  EXPECT_EQ(k.speeds_from_rest, 1);
  const std::vector<KickObservation>& o = k.by_kick.at("forward");
  EXPECT_DOUBLE_EQ(o[0].launch_speed_mps, 1.0);
  EXPECT_FALSE(o[0].has_roll_distance);
  EXPECT_NEAR(o[1].launch_speed_mps, std::sqrt(2.0 * kA * 2.0), 1e-12);
  EXPECT_NEAR(o[1].launch_direction_rad, 0.0, 1e-12);
  EXPECT_FALSE(o[1].has_roll_distance);
  EXPECT_TRUE(o[2].has_roll_distance);
  EXPECT_NEAR(o[2].roll_distance_m, 2.5, 1e-12);
}

struct BadCsv {
  std::string name;
  std::string text;
  std::vector<std::string> message_parts;  // besides the file name
};

TEST(ObservedKicksTest, ErrorsAreOneLineNamingFileLineAndColumn) {
  const std::string launch = kPose + ",launch_speed_mps,launch_direction_deg\n";
  const std::string row = "forward,0,0,0,0.15,0,1.0,0\n";
  const std::vector<BadCsv> cases = {
      {"unknown_column", kPose + ",spin_rpm\nforward,0,0,0,0,0,3\n", {"line 1", "spin_rpm"}},
      {"missing_column",
       "kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,launch_speed_mps\n",
       {"line 1", "ball_y_m"}},
      {"duplicate_column", kPose + ",ball_x_m\n", {"line 1", "ball_x_m"}},
      {"not_a_number",
       launch + row + "forward,0,abc,0,0.15,0,1.0,0\n",
       {"line 3", "robot_y_m", "abc"}},
      {"trailing_text",
       launch + "forward,0,0,0,0.15,0,1.5m,0\n",
       {"line 2", "launch_speed_mps", "1.5m"}},
      {"not_finite", launch + "forward,0,0,0,0.15,0,1.0,nan\n", {"line 2", "launch_direction_deg"}},
      {"missing_required_cell",
       launch + "forward,0,0,,0.15,0,1.0,0\n",
       {"line 2", "robot_theta_deg"}},
      {"neither_launch_nor_rest",
       launch + row + row + "forward,0,0,0,0.15,0,,\n",
       {"line 4", "launch_speed_mps"}},
      {"neither_without_columns",
       kPose + "\nforward,0,0,0,0.15,0\n",
       {"line 2", "launch_speed_mps"}},
      {"half_a_launch", launch + "forward,0,0,0,0.15,0,1.0,\n", {"line 2", "launch_direction_deg"}},
      {"half_a_rest",
       kPose + ",rest_x_m,rest_y_m\nforward,0,0,0,0.15,0,,2\n",
       {"line 2", "rest_x_m"}},
      {"negative_speed", launch + "forward,0,0,0,0.15,0,-1,0\n", {"line 2", "launch_speed_mps"}},
      {"missing_kick_name", launch + ",0,0,0,0.15,0,1.0,0\n", {"line 2", "kick: missing"}},
      {"too_few_cells", launch + row + "forward,0,0,0,0.15,0,1.0\n", {"line 3", "7 cells"}},
      {"too_many_cells", launch + "forward,0,0,0,0.15,0,1.0,0,9\n", {"line 2", "9 cells"}},
      {"absurd_coordinate",
       kPose + ",rest_x_m,rest_y_m\nforward,0,0,0,0.15,0,1e200,0.1\n",
       {"line 2", "rest_x_m", "must be within [-100, 100]", "1e200"}},
      {"absurd_speed",
       launch + "forward,0,0,0,0.15,0,340,0\n",
       {"line 2", "launch_speed_mps", "340"}},
      {"absurd_heading", launch + "forward,0,0,1e9,0.15,0,1.0,0\n", {"line 2", "robot_theta_deg"}},
      {"empty_file", "", {"no header"}},
      {"header_only", launch, {"no kicks"}},
      // RFC 4180 quoting gone wrong.
      {"unclosed_quote", launch + "\"forward,0,0,0,0.15,0,1,0\n", {"line 2", "never closed"}},
      {"after_quote", launch + "\"forward\"x,0,0,0,0.15,0,1,0\n", {"line 2", "closing quote"}},
      {"quote_inside", launch + "for\"ward,0,0,0,0.15,0,1,0\n", {"line 2", "unquoted cell"}},
  };
  for (const BadCsv& c : cases) {
    SCOPED_TRACE(c.name);
    const auto file = Csv(c.name, c.text);
    try {
      ReadObservedKicks(file, kA);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_THAT(message, ::testing::StartsWith(file.string() + ": "));
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      for (const std::string& part : c.message_parts) EXPECT_THAT(message, HasSubstr(part));
    }
  }
}

TEST(ObservedKicksTest, QuotedCellsAfterRfc4180) {
  // Quoted header and cells, a comma and a doubled quote inside quotes, a line break inside a
  // quoted cell, CRLF line ends, spaces around quotes.
  const auto file = Csv("quoted",
                        "\"kick\",\"robot_x_m\",robot_y_m,robot_theta_deg,ball_x_m,ball_y_m,"
                        "\"launch_speed_mps\",launch_direction_deg\r\n"
                        "\"forward\",\"0\",0,0,0.15,0, \"1.05\" ,\"-3\"\r\n"
                        "\"side, \"\"left\"\"\",1,2,90,1,2.15,0.7,92.5\r\n"
                        "\"two\nlines\",0,0,0,0.15,0,1.1,4\r\n"
                        "forward,0,0,0,0.15,0,1.2,2\r\n");
  const ObservedKicks k = ReadObservedKicks(file, kA);
  EXPECT_EQ(k.rows, 4);
  EXPECT_EQ(k.kick_names,
            (std::vector<std::string>{"forward", "side, \"left\"", "two\nlines"}));
  ASSERT_EQ(k.by_kick.at("forward").size(), 2u);
  EXPECT_DOUBLE_EQ(k.by_kick.at("forward")[0].launch_speed_mps, 1.05);
  EXPECT_NEAR(k.by_kick.at("forward")[0].launch_direction_rad, -3.0 * kDegToRad, 1e-12);
  // Line numbers count the line break inside the quoted cell.
  ASSERT_EQ(k.row_list.size(), 4u);
  EXPECT_EQ(k.row_list[2].line, 4);
  EXPECT_EQ(k.row_list[3].line, 6);
}

// A kick model like the NAO's: forward straight ahead, the side kick to the left, 5 deg sigma.
KickModel TwoKicks() {
  KickModel model;
  model.robot = "nao";
  model.rolling_deceleration_mps2 = kA;
  model.kicks = {{"forward", 1.0, 0.1, 0.0, 5.0 * kDegToRad, 0.0},
                 {"side_kick_left", 0.7, 0.1, 85.0 * kDegToRad, 5.0 * kDegToRad, 0.0}};
  return model;
}

std::string CheckError(const std::filesystem::path& file) {
  try {
    CheckObservedKicks(ReadObservedKicks(file, kA), TwoKicks(), file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kBoth = kPose + ",launch_speed_mps,launch_direction_deg,rest_x_m,rest_y_m\n";

TEST(ObservedKicksTest, ConsistentLaunchAndRestPass) {
  // Robot at the origin facing +x, ball 0.15 ahead; the side kick rolls 1 m at 85 deg, logged
  // 87 deg (2 deg off: within 3 x 5 deg).
  const double c = std::cos(85.0 * kDegToRad), s = std::sin(85.0 * kDegToRad);
  const auto file = Csv("consistent", kBoth + "side_kick_left,0,0,0,0.15,0,0.7,87," +
                                          std::to_string(0.15 + c) + "," + std::to_string(s) +
                                          "\nforward,0,0,0,0.15,0,1.0,-1,2.15,0\n");
  EXPECT_EQ(CheckError(file), "");
}

TEST(ObservedKicksTest, RadiansInARowWithARestAreRefusedNamingTheRow) {
  const double c = std::cos(85.0 * kDegToRad), s = std::sin(85.0 * kDegToRad);
  const auto file = Csv("radian_row", kBoth + "forward,0,0,0,0.15,0,1.0,-1,2.15,0\n" +
                                          "side_kick_left,0,0,0,0.15,0,0.7,1.48," +
                                          std::to_string(0.15 + c) + "," + std::to_string(s) + "\n");
  const std::string message = CheckError(file);
  EXPECT_THAT(message, ::testing::StartsWith(file.string() + ": line 3: launch_direction_deg: 1.48"));
  EXPECT_THAT(message, HasSubstr("looks like radians"));
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(ObservedKicksTest, ContradictingLaunchAndRestAreNamedWithTheAllowance) {
  // The launch says 60 deg, the rest lies at 85 deg: 25 deg apart, more than 3 x 5 deg.
  const double c = std::cos(85.0 * kDegToRad), s = std::sin(85.0 * kDegToRad);
  const auto file = Csv("contradiction", kBoth + "side_kick_left,0,0,0,0.15,0,0.7,60," +
                                             std::to_string(0.15 + c) + "," + std::to_string(s) +
                                             "\n");
  const std::string message = CheckError(file);
  EXPECT_THAT(message, HasSubstr(": line 2: launch_direction_deg: 60"));
  EXPECT_THAT(message, HasSubstr("contradicts the rest position's bearing 85.0 deg"));
  EXPECT_THAT(message, HasSubstr("by 25.0 deg, more than 3 x sigma_direction (15.0 deg)"));
  EXPECT_THAT(message, Not(HasSubstr("radians")));
}

TEST(ObservedKicksTest, LaunchOnlyRadiansAreRefusedNamingTheFirstRow) {
  // Side kicks logged in radians (about 1.48 = 85 deg), no rest positions to compare with.
  const std::string launch = kPose + ",launch_speed_mps,launch_direction_deg\n";
  const auto file = Csv("radian_kick", launch + "forward,0,0,0,0.15,0,1.0,3\n" +
                                           "side_kick_left,0,0,0,0.15,0,0.7,1.50\n" +
                                           "side_kick_left,0,0,0,0.15,0,0.7,1.45\n" +
                                           "side_kick_left,0,0,0,0.15,0,0.7,1.49\n");
  const std::string message = CheckError(file);
  EXPECT_THAT(message, HasSubstr(": line 3: launch_direction_deg: the 3 launches of "
                                 "'side_kick_left' look like radians"));
  // The same kicks in degrees pass, and so does a forward kick whose directions are all small.
  const auto degrees = Csv("degree_kick", launch + "forward,0,0,0,0.15,0,1.0,0.5\n" +
                                              "forward,0,0,0,0.15,0,1.0,-1.2\n" +
                                              "side_kick_left,0,0,0,0.15,0,0.7,86\n" +
                                              "side_kick_left,0,0,0,0.15,0,0.7,83\n");
  EXPECT_EQ(CheckError(degrees), "");
}

TEST(ObservedKicksTest, RestOnlySpeedsAreDerivedAgainWithAGivenDeceleration) {
  const auto file = Csv("rederive", kBoth + "forward,0,0,0,0,0,,,2,0\n" +
                                        "forward,0,0,0,0,0,1.2,0,2.5,0\n");
  ObservedKicks k = ReadObservedKicks(file, kA);
  std::vector<KickObservation>& o = k.by_kick.at("forward");
  EXPECT_TRUE(o[0].speed_from_rest);
  EXPECT_FALSE(o[1].speed_from_rest);
  RederiveSpeedsFromRest(o, 0.5, 0.05);
  EXPECT_NEAR(o[0].launch_speed_mps, std::sqrt(2.0 * 0.5 * (2.0 - 0.05)), 1e-12);
  EXPECT_DOUBLE_EQ(o[1].launch_speed_mps, 1.2);  // a logged launch stays
}

TEST(ObservedKicksTest, MissingFileIsAnInputError) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "foresight_tests" /
      ("observed_kicks_test_absent_" + std::to_string(::getpid()) + ".csv");
  try {
    ReadObservedKicks(file, kA);
    FAIL() << "a missing file was read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string()));
  }
}

}  // namespace
}  // namespace foresight
