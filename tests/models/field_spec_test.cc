#include "models/field_spec.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

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

// The shipped SPL field with `from` replaced by `to`, written to a temporary file.
std::filesystem::path BrokenSplField(const std::string& name, const std::string& from,
                                     const std::string& to) {
  return BrokenShipped("fields/spl.json", "field_spec_" + name, from, to);
}

std::string LoadError(const std::filesystem::path& file) {
  return InputErrorMessage([&] { LoadFieldSpec(file); });
}

TEST(FieldSpecTest, ShippedSplFieldHasTheRuleBookDimensions) {
  const FieldSpec f = LoadFieldSpec(ModelsDir() / "fields" / "spl.json");
  EXPECT_EQ(f.name, "spl");
  EXPECT_DOUBLE_EQ(f.field_length_m, 9.0);
  EXPECT_DOUBLE_EQ(f.field_width_m, 6.0);
  EXPECT_DOUBLE_EQ(f.carpet_length_m, 10.4);
  EXPECT_DOUBLE_EQ(f.carpet_width_m, 7.4);
  EXPECT_DOUBLE_EQ(f.goal.post_centre_x_m, 4.525);
  EXPECT_DOUBLE_EQ(f.goal.post_centre_y_m, 0.8);
  EXPECT_DOUBLE_EQ(f.goal.post_radius_m, 0.05);
  EXPECT_DOUBLE_EQ(f.goal.net_depth_m, 0.5);
  EXPECT_DOUBLE_EQ(f.goal.net_height_m, 0.8);
  EXPECT_DOUBLE_EQ(f.ball.radius_m, 0.05);
  EXPECT_DOUBLE_EQ(f.ball.mass_kg, 0.045);
}

TEST(FieldSpecTest, SplDerivedSizesFollowFromTheFile) {
  const FieldSpec f = LoadFieldSpec(ModelsDir() / "fields" / "spl.json");
  EXPECT_DOUBLE_EQ(f.HalfLength(), 4.5);
  EXPECT_DOUBLE_EQ(f.HalfWidth(), 3.0);
  EXPECT_DOUBLE_EQ(f.CarpetHalfLength(), 5.2);
  EXPECT_DOUBLE_EQ(f.CarpetHalfWidth(), 3.7);
  // Inner goal width 1.5 m: posts at +-0.8 with radius 0.05.
  EXPECT_DOUBLE_EQ(2.0 * f.goal.InnerHalfWidth(), 1.5);
}

TEST(FieldSpecTest, ShippedFourLeggedFieldHasTheAiboDimensions) {
  const FieldSpec f = LoadFieldSpec(ModelsDir() / "fields" / "four_legged.json");
  EXPECT_EQ(f.name, "four_legged");
  EXPECT_DOUBLE_EQ(f.field_length_m, 5.4);
  EXPECT_DOUBLE_EQ(f.field_width_m, 3.6);
  EXPECT_DOUBLE_EQ(f.HalfLength(), 2.7);
  EXPECT_DOUBLE_EQ(f.HalfWidth(), 1.8);
  EXPECT_NEAR(2.0 * f.goal.InnerHalfWidth(), 0.8, 1e-12);  // goal 0.8 m wide
  EXPECT_DOUBLE_EQ(f.goal.net_depth_m, 0.3);
  EXPECT_DOUBLE_EQ(f.ball.radius_m, 0.042);
  EXPECT_DOUBLE_EQ(f.ball.mass_kg, 0.03);  // undocumented in the rules; the project's choice
}

TEST(FieldSpecTest, MissingFileNamesThePath) {
  const std::filesystem::path file = ModelsDir() / "fields" / "spl_2099.json";
  EXPECT_EQ(LoadError(file), file.string() + ": cannot open file");
}

TEST(FieldSpecTest, SyntaxErrorNamesFileLineAndColumn) {
  // Drop the comma after the field length: the parser stops on line 5 at the end of the next
  // key, "field_width_m" (columns 3 to 17).
  const auto file = BrokenSplField("syntax", "\"field_length_m\": 9.0,", "\"field_length_m\": 9.0");
  EXPECT_THAT(LoadError(file), StartsWith(file.string() + ": invalid JSON at line 5, column 17: "));
}

TEST(FieldSpecTest, TypoInNestedKeyIsAnUnknownField) {
  const auto file = BrokenSplField("typo", "\"post_radius_m\"", "\"post_radius\"");
  EXPECT_EQ(LoadError(file), file.string() + ": goal.post_radius: unknown field");
}

TEST(FieldSpecTest, TypoInTopLevelKeyIsAnUnknownField) {
  const auto file = BrokenSplField("typo_top", "\"carpet_width_m\"", "\"carpet_widht_m\"");
  EXPECT_EQ(LoadError(file), file.string() + ": carpet_widht_m: unknown field");
}

TEST(FieldSpecTest, NumberGivenAsStringNamesTheValue) {
  const auto file =
      BrokenSplField("type", "\"field_length_m\": 9.0", "\"field_length_m\": \"9.0\"");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": field_length_m: must be a number"));
  EXPECT_THAT(message, HasSubstr("\"9.0\""));
}

TEST(FieldSpecTest, MissingBallObjectIsReported) {
  const auto file = BrokenSplField(
      "no_ball",
      "\"ball\": {\n    \"radius_m\": 0.05,\n    \"mass_kg\": 0.045,\n    \"inertia_factor\": 0.4\n  },",
      "");
  EXPECT_EQ(LoadError(file), file.string() + ": ball: missing");
}

TEST(FieldSpecTest, InertiaFactorBeyondAShellIsRejected) {
  const auto file =
      BrokenSplField("shell", "\"inertia_factor\": 0.4", "\"inertia_factor\": 0.8");
  EXPECT_EQ(LoadError(file),
            file.string() + ": ball.inertia_factor: must be in [0.4, 0.6666666666666666], got 0.8");
}

TEST(FieldSpecTest, InertiaFactorIsRequired) {
  const auto file = BrokenSplField("no_inertia", ",\n    \"inertia_factor\": 0.4", "");
  EXPECT_EQ(LoadError(file), file.string() + ": ball.inertia_factor: missing");
}

TEST(FieldSpecTest, NegativePostRadiusNamesFieldAndValue) {
  const auto file =
      BrokenSplField("negative_post", "\"post_radius_m\": 0.05", "\"post_radius_m\": -0.05");
  EXPECT_EQ(LoadError(file), file.string() + ": goal.post_radius_m: must be > 0, got -0.05");
}

// Issue 16: finite but absurd sizes used to pass and produce silent nonsense.
TEST(FieldSpecTest, ImplausibleSizesAreRejected) {
  const auto huge =
      BrokenSplField("huge_field", "\"field_length_m\": 9.0", "\"field_length_m\": 1e308");
  EXPECT_THAT(LoadError(huge), StartsWith(huge.string() + ": field_length_m: must be in [0, 200]"));
  const auto heavy = BrokenSplField("heavy_ball", "\"mass_kg\": 0.045", "\"mass_kg\": 1e9");
  EXPECT_THAT(LoadError(heavy), HasSubstr("ball.mass_kg: must be in [0, 10]"));
}

TEST(FieldSpecTest, ZeroBallMassIsRejected) {
  const auto file = BrokenSplField("zero_mass", "\"mass_kg\": 0.045", "\"mass_kg\": 0");
  EXPECT_EQ(LoadError(file), file.string() + ": ball.mass_kg: must be > 0, got 0");
}

TEST(FieldSpecTest, CarpetSmallerThanTheFieldIsRejected) {
  const auto file =
      BrokenSplField("small_carpet", "\"carpet_length_m\": 10.4", "\"carpet_length_m\": 8.0");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": carpet_length_m: must be in [9, "));
  EXPECT_THAT(message, HasSubstr("got 8"));
}

TEST(FieldSpecTest, BallWiderThanTheGoalMouthIsRejected) {
  const auto file = BrokenSplField("huge_ball", "\"radius_m\": 0.05", "\"radius_m\": 0.9");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": ball.radius_m: must be in ["));
  EXPECT_THAT(message, HasSubstr("got 0.9"));
}

TEST(FieldSpecTest, ValidateAloneNamesTheFieldWithoutAFile) {
  FieldSpec f = LoadFieldSpec(ModelsDir() / "fields" / "spl.json");
  f.field_width_m = -6.0;
  EXPECT_EQ(InputErrorMessage([&] { f.Validate(); }), "field_width_m: must be > 0, got -6");
}

}  // namespace
}  // namespace foresight
