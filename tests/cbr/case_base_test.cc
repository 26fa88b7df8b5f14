// The case base: the shipped cases load into 156, indexed by defending goal; the loader's rules
// for settings, folders and lists; the overlap check.
#include "cbr/case_base.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

std::filesystem::path ShippedCases() {
  return DefaultCaseBasePath(testing::ModelsDir());
}

TEST(CaseBaseTest, ShippedBaseHas39HandWrittenAnd156Cases) {
  const LoadedCaseBase loaded = LoadCaseBase(ShippedCases(), testing::ModelsDir());
  EXPECT_EQ(loaded.cases.HandWrittenCount(), 39u);
  EXPECT_EQ(loaded.cases.size(), 156u);
  EXPECT_EQ(loaded.cases.Defending(DefendingGoal::kCyan).size(), 78u);
  EXPECT_EQ(loaded.cases.Defending(DefendingGoal::kYellow).size(), 78u);
  for (const Case& c : loaded.cases.Defending(DefendingGoal::kYellow)) {
    EXPECT_EQ(c.defending, DefendingGoal::kYellow) << c.name;
    EXPECT_FALSE(c.notes.empty()) << c.name;
  }
  EXPECT_EQ(loaded.kick_mirrors.at("head_kick_right"), "head_kick_left");
  EXPECT_TRUE(CheckCaseBase(loaded.cases).empty());
}

TEST(CaseBaseTest, EveryCopyKeepsTheRules) {
  const LoadedCaseBase loaded = LoadCaseBase(ShippedCases(), testing::ModelsDir());
  for (DefendingGoal goal : {DefendingGoal::kCyan, DefendingGoal::kYellow}) {
    for (const Case& c : loaded.cases.Defending(goal)) {
      EXPECT_NO_THROW(ValidateCase(c, loaded.rules)) << c.name;
    }
  }
}

// models/cases/README.md: about 95% of the midfield and attacking half (x >= -0.9 m) lies in a
// ball scope, for either defending goal (the yellow copies mirror the cyan ones).
TEST(CaseBaseTest, ShippedBallScopesCoverMostOfTheAttack) {
  const LoadedCaseBase loaded = LoadCaseBase(ShippedCases(), testing::ModelsDir());
  EXPECT_GT(BallScopeCoverage(loaded, DefendingGoal::kCyan, -0.9, 2.7, 0.05), 0.94);
  EXPECT_NEAR(BallScopeCoverage(loaded, DefendingGoal::kYellow, -2.7, 0.9, 0.05),
              BallScopeCoverage(loaded, DefendingGoal::kCyan, -0.9, 2.7, 0.05), 0.01);
}

TEST(CaseBaseTest, CopiesAreNamedAndMirrored) {
  const LoadedCaseBase loaded = LoadCaseBase(ShippedCases(), testing::ModelsDir());
  const Case* original = loaded.cases.Find("front_pass_dg");
  const Case* copy = loaded.cases.Find("front_pass_dg/mirror_x");
  ASSERT_NE(original, nullptr);
  ASSERT_NE(copy, nullptr);
  EXPECT_EQ(copy->source, "front_pass_dg");
  EXPECT_EQ(copy->transform, CaseTransform::kMirrorX);
  EXPECT_EQ(copy->defending, DefendingGoal::kYellow);
  EXPECT_EQ(copy->p_F_ball, Vec2(-original->p_F_ball.x(), original->p_F_ball.y()));
  EXPECT_EQ(original->teammates[0].actions[1].kick, "head_kick_left");
  EXPECT_EQ(copy->teammates[0].actions[1].kick, "head_kick_right");
  EXPECT_EQ(copy->teammates[0].actions[1].teammate, 2);
  EXPECT_NE(loaded.cases.Find("front_pass_dg/mirror_y"), nullptr);
  EXPECT_NE(loaded.cases.Find("front_pass_dg/mirror_xy"), nullptr);
  EXPECT_EQ(loaded.cases.Find("front_pass_dg/original"), nullptr);
}

TEST(CaseBaseTest, ReportsACaseSymmetricInYAsAnOverlap) {
  Case c;
  c.name = c.source = "centre";
  c.ball_scope = {0.5, 0.5};
  CaseAction get_ball;
  get_ball.type = ActionType::kGetBall;
  c.teammates = {{1, Vec2(-0.3, 0.0), {get_ball}}};
  const CaseBase base({c}, {});
  const auto warnings = CheckCaseBase(base);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "centre and centre/mirror_y are identical");
  EXPECT_EQ(warnings[1], "centre/mirror_x and centre/mirror_xy are identical");
}

std::string CopyCase(const std::string& name, const std::string& to_folder) {
  const auto dir = std::filesystem::temp_directory_path() / "foresight_tests" / to_folder;
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(ShippedCases() / (name + ".json"), dir / (name + ".json"),
                             std::filesystem::copy_options::overwrite_existing);
  return dir.string();
}

std::string LoadError(const std::filesystem::path& path) {
  try {
    LoadCaseBase(path, testing::ModelsDir());
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CaseBaseTest, ASettingsFileListsItsCases) {
  const std::string dir = CopyCase("back_pass", "list_base");
  std::ofstream(dir + "/base.json")
      << R"({"field": "four_legged", "kicks": "aibo_ers7", "kick_mirrors": {}, "cases": ["back_pass.json"]})";
  EXPECT_EQ(LoadCaseBase(dir + "/base.json", testing::ModelsDir()).cases.size(), 4u);
}

TEST(CaseBaseTest, SettingsErrors) {
  const std::string dir = CopyCase("back_pass", "bad_base");
  auto settings = [&](const std::string& text) {
    std::ofstream(dir + "/case_base.json") << text;
    return LoadError(dir);
  };
  EXPECT_THAT(
      settings(
          R"({"field": "four_legged", "kicks": "aibo_ers7", "kick_mirrors": {"left": "head_kick_right"}})"),
      HasSubstr("kick_mirrors.left: unknown kick 'left'"));
  EXPECT_THAT(
      settings(
          R"({"field": "four_legged", "kicks": "aibo_ers7", "kick_mirrors": {}, "mirror": 1})"),
      HasSubstr("mirror: unknown field"));
  EXPECT_THAT(settings(R"({"field": "nowhere", "kicks": "aibo_ers7", "kick_mirrors": {}})"),
              HasSubstr("field: refers to"));
  settings(R"({"field": "four_legged", "kicks": "aibo_ers7", "kick_mirrors": {}})");
  EXPECT_THAT(LoadError(dir + "/case_base.json"), HasSubstr("cases: missing"));
  std::filesystem::remove(dir + "/case_base.json");
  EXPECT_THAT(LoadError(dir), HasSubstr("case_base.json: does not exist"));
}

TEST(CaseBaseTest, HandWrittenNamesAreUnique) {
  const std::string dir = CopyCase("back_pass", "twice_base");
  std::filesystem::copy_file(ShippedCases() / "back_pass.json", dir + "/back_pass_copy.json",
                             std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(ShippedCases() / "case_base.json", dir + "/case_base.json",
                             std::filesystem::copy_options::overwrite_existing);
  EXPECT_THAT(LoadError(dir), HasSubstr("back_pass_copy.json: case back_pass: name: used by"));
}

}  // namespace
}  // namespace foresight
