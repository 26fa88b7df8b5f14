// Problem files: a good one loads; each rule fails with a message naming the file and field.
#include "cbr/problem.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

const std::string kGood = R"({"defending": "yellow", "ball": {"x_m": -1.0, "y_m": 0.2},
  "teammates": [{"id": 2, "x_m": -0.8, "y_m": 0.2, "theta_deg": 180},
                {"id": 1, "x_m": 0.5, "y_m": -1.0, "theta_deg": 90}],
  "opponents": [{"x_m": -2.0, "y_m": 0.0}]})";

Problem Load(const std::string& text) {
  return LoadProblem(testing::WriteTempFile("problem.json", text), testing::ModelsDir());
}

std::string Error(const std::string& from, const std::string& to) {
  std::string text = kGood;
  text.replace(text.find(from), from.size(), to);
  try {
    Load(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ProblemTest, LoadsAProblem) {
  const Problem p = Load(kGood);
  EXPECT_EQ(p.defending, DefendingGoal::kYellow);
  EXPECT_EQ(p.p_F_ball, Vec2(-1.0, 0.2));
  ASSERT_EQ(p.teammates.size(), 2u);
  EXPECT_EQ(p.teammates[0].id, 2);
  EXPECT_NEAR(p.teammates[0].pose.theta_rad, kPi, 1e-12);
  ASSERT_EQ(p.opponents.size(), 1u);
}

TEST(ProblemTest, Errors) {
  EXPECT_THAT(Error(R"("id": 2)", R"("id": 0)"),
              HasSubstr("problem.json: teammates[0].id: must be 1..4, got 0"));
  EXPECT_THAT(Error(R"("id": 2)", R"("id": 1)"),
              HasSubstr("problem.json: teammates[1].id: 1 is used twice"));
  EXPECT_THAT(Error(R"("x_m": -1.0)", R"("x_m": -2.8)"),
              HasSubstr("problem.json: ball.x_m: (-2.8, 0.2) is off the field"));
  EXPECT_THAT(Error(R"("x_m": -2.0)", R"("x_m": -2.0, "theta_deg": 0)"),
              HasSubstr("problem.json: opponents[0].theta_deg: unknown field"));
  EXPECT_THAT(Error("yellow", "green"), HasSubstr("defending: must be \"cyan\" or \"yellow\""));
  EXPECT_THAT(Error(R"("theta_deg": 90)", R"("theta_deg": 900)"),
              HasSubstr("teammates[1].theta_deg: must be in [-360, 360], got 900"));
  EXPECT_THAT(Error(R"("teammates": [)", R"("teammates": [], "x": [)"),
              HasSubstr("x: unknown field"));
  const std::string opp = R"({"x_m": 0, "y_m": 0}, )";
  EXPECT_THAT(Error(R"("opponents": [)", R"("opponents": [)" + opp + opp + opp + opp),
              HasSubstr("opponents: must list 0-4 robots, got 5"));
}

}  // namespace
}  // namespace foresight
