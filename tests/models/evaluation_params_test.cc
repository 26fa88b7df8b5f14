#include "models/evaluation_params.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/geometry.h"
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

std::filesystem::path BrokenSplEvaluation(const std::string& name, const std::string& from,
                                          const std::string& to) {
  return BrokenShipped("evaluation/spl.json", "evaluation_params_" + name, from, to);
}

std::string LoadError(const std::filesystem::path& file) {
  return InputErrorMessage([&] { LoadEvaluationParams(file); });
}

TEST(EvaluationParamsTest, ShippedSplThresholdsAreThePapers) {
  const EvaluationParams p = LoadEvaluationParams(ModelsDir() / "evaluation" / "spl.json");
  EXPECT_EQ(p.name, "spl");
  EXPECT_DOUBLE_EQ(p.max_out_share, 0.15);  // T_out
  EXPECT_EQ(p.samples, 30);                 // N
  EXPECT_DOUBLE_EQ(p.goal_value, 1.0);
  EXPECT_DOUBLE_EQ(p.naoth_rule.min_acceptable_share, 0.85);
  EXPECT_DOUBLE_EQ(p.naoth_rule.goal_preference_share, 0.30);
}

TEST(EvaluationParamsTest, ShippedSplPotentialIsTheNaothStrategy) {
  // f(x, y) = -x / 4.5 - G(x, y; 4.5, 0; 2.25, 1.2) + G(x, y; -4.5, 0; 3.375, 1.2)
  const EvaluationParams p = LoadEvaluationParams(ModelsDir() / "evaluation" / "spl.json");
  EXPECT_DOUBLE_EQ(p.potential.linear_x_scale_m, 4.5);
  ASSERT_EQ(p.potential.gaussians.size(), 2u);
  const GaussianTerm& attract = p.potential.gaussians[0];
  EXPECT_DOUBLE_EQ(attract.weight, -1.0);
  EXPECT_DOUBLE_EQ(attract.centre_x_m, 4.5);
  EXPECT_DOUBLE_EQ(attract.centre_y_m, 0.0);
  EXPECT_DOUBLE_EQ(attract.sigma_x_m, 2.25);
  EXPECT_DOUBLE_EQ(attract.sigma_y_m, 1.2);
  const GaussianTerm& repel = p.potential.gaussians[1];
  EXPECT_DOUBLE_EQ(repel.weight, 1.0);
  EXPECT_DOUBLE_EQ(repel.centre_x_m, -4.5);
  EXPECT_DOUBLE_EQ(repel.sigma_x_m, 3.375);
  EXPECT_DOUBLE_EQ(repel.sigma_y_m, 1.2);
}

TEST(EvaluationParamsTest, ShippedFilesKeepThePapersInelasticContacts) {
  for (const char* name : {"spl.json", "four_legged.json"}) {
    const EvaluationParams p = LoadEvaluationParams(ModelsDir() / "evaluation" / name);
    EXPECT_FALSE(p.rebounds.enabled) << name;
    EXPECT_EQ(p.rebounds.max_contacts, 8) << name;
    EXPECT_EQ(p.rebounds.post, 0.0) << name;  // read from the physics file only when enabled
  }
}

TEST(EvaluationParamsTest, ReboundsSwitchMustBeABoolean) {
  const auto file = BrokenSplEvaluation("rebounds", "\"enabled\": false", "\"enabled\": \"no\"");
  EXPECT_EQ(LoadError(file),
            file.string() + ": rebounds.enabled: must be true or false, got \"no\"");
}

TEST(EvaluationParamsTest, ZeroMaxContactsIsRejected) {
  const auto file = BrokenSplEvaluation("contacts", "\"max_contacts\": 8", "\"max_contacts\": 0");
  EXPECT_THAT(LoadError(file),
              StartsWith(file.string() + ": rebounds.max_contacts: must be in [1"));
}

TEST(EvaluationParamsTest, RotationSearchStepIsConvertedToRadians) {
  const EvaluationParams p = LoadEvaluationParams(ModelsDir() / "evaluation" / "spl.json");
  EXPECT_NEAR(p.rotation_search.grid_step_rad, 20.0 * kDegToRad, 1e-15);
  EXPECT_EQ(p.rotation_search.refine_levels, 5);
  EXPECT_EQ(p.rotation_search.refine_candidates, 1);
  EXPECT_EQ(p.rotation_search.coarse_sample_share, 0.25);
  EXPECT_EQ(p.rotation_search.CoarseSamples(30), 8);  // ceil(7.5)
  EXPECT_EQ(p.rotation_search.CoarseSamples(4), 1);
  EXPECT_EQ(p.rotation_search.CoarseSamples(1), 1);
  RotationSearchParams third = p.rotation_search;
  third.coarse_sample_share = 1.0 / 3;
  EXPECT_EQ(third.CoarseSamples(30), 10);  // not 11 from rounding
}

TEST(EvaluationParamsTest, CoarseShareOutsideItsRangeIsRejected) {
  const auto file = BrokenSplEvaluation("coarse", "\"coarse_sample_share\": 0.25",
                                        "\"coarse_sample_share\": 0");
  EXPECT_THAT(LoadError(file),
              StartsWith(file.string() + ": rotation_search.coarse_sample_share: must be in ["));
}

TEST(EvaluationParamsTest, ShippedFourLeggedIsTheSplStrategyScaled) {
  const EvaluationParams p = LoadEvaluationParams(ModelsDir() / "evaluation" / "four_legged.json");
  EXPECT_EQ(p.name, "four_legged");
  EXPECT_DOUBLE_EQ(p.potential.linear_x_scale_m, 2.7);
  ASSERT_EQ(p.potential.gaussians.size(), 2u);
  EXPECT_DOUBLE_EQ(p.potential.gaussians[0].centre_x_m, 2.7);
  EXPECT_DOUBLE_EQ(p.potential.gaussians[1].centre_x_m, -2.7);
  EXPECT_DOUBLE_EQ(p.max_out_share, 0.15);
  EXPECT_EQ(p.samples, 30);
}

TEST(EvaluationParamsTest, ZeroSamplesIsRejected) {
  const auto file = BrokenSplEvaluation("zero_samples", "\"samples\": 30", "\"samples\": 0");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": samples: must be in [1, "));
  EXPECT_THAT(message, HasSubstr("got 0"));
}

// Issue 16: a subnormal scale made the value NaN (and crashed decide); huge weights overflow it.
TEST(EvaluationParamsTest, ImplausibleScalesAndWeightsAreRejected) {
  const auto tiny = BrokenSplEvaluation("tiny_scale", "\"linear_x_scale_m\": 4.5",
                                        "\"linear_x_scale_m\": 1e-310");
  EXPECT_THAT(LoadError(tiny),
              StartsWith(tiny.string() + ": potential.linear_x_scale_m: must be in [0.01, 1000]"));
  const auto heavy = BrokenSplEvaluation("heavy", "\"weight\": -1.0", "\"weight\": -1e300");
  EXPECT_THAT(LoadError(heavy), HasSubstr("potential.gaussians[0].weight: must be in"));
}

TEST(EvaluationParamsTest, FractionalSamplesIsNotAnInteger) {
  const auto file = BrokenSplEvaluation("fraction_samples", "\"samples\": 30", "\"samples\": 30.5");
  EXPECT_EQ(LoadError(file), file.string() + ": samples: must be an integer, got 30.5");
}

TEST(EvaluationParamsTest, OutShareAboveOneIsRejected) {
  const auto file =
      BrokenSplEvaluation("out_share", "\"max_out_share\": 0.15", "\"max_out_share\": 1.5");
  EXPECT_EQ(LoadError(file), file.string() + ": max_out_share: must be in [0, 1], got 1.5");
}

TEST(EvaluationParamsTest, NegativeGaussianSigmaNamesTheTerm) {
  const auto file =
      BrokenSplEvaluation("negative_sigma", "\"sigma_x_m\": 3.375", "\"sigma_x_m\": -3.375");
  EXPECT_EQ(LoadError(file),
            file.string() + ": potential.gaussians[1].sigma_x_m: must be > 0, got -3.375");
}

TEST(EvaluationParamsTest, TypoInTopLevelKeyIsAnUnknownField) {
  const auto file = BrokenSplEvaluation("typo", "\"max_out_share\"", "\"max_out_shares\"");
  EXPECT_EQ(LoadError(file), file.string() + ": max_out_shares: unknown field");
}

TEST(EvaluationParamsTest, TypoInsideGaussianIsAnUnknownField) {
  const auto file = BrokenSplEvaluation("typo_gaussian", "\"weight\": 1.0", "\"weigth\": 1.0");
  EXPECT_EQ(LoadError(file), file.string() + ": potential.gaussians[1].weigth: unknown field");
}

TEST(EvaluationParamsTest, ShareGivenAsStringNamesTheValue) {
  const auto file = BrokenSplEvaluation("type", "\"min_acceptable_share\": 0.85",
                                        "\"min_acceptable_share\": \"85%\"");
  EXPECT_EQ(LoadError(file),
            file.string() + ": naoth_rule.min_acceptable_share: must be a number, got \"85%\"");
}

TEST(EvaluationParamsTest, TooFineRotationGridIsRejected) {
  const auto file =
      BrokenSplEvaluation("grid", "\"grid_step_deg\": 20.0", "\"grid_step_deg\": 0.01");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": rotation_search.grid_step_deg: must be in ["));
  EXPECT_THAT(message, HasSubstr("got 0.01"));
}

TEST(EvaluationParamsTest, MissingRotationSearchIsNamed) {
  const std::string text = ReplaceOnce(
      ShippedText("evaluation/spl.json"),
      ",\n  \"rotation_search\": {\n    \"grid_step_deg\": 20.0,\n    \"refine_levels\": 5,\n"
      "    \"refine_candidates\": 1,\n    \"coarse_sample_share\": 0.25\n  }",
      "");
  const auto file = WriteTempFile("evaluation_params_no_search.json", text);
  EXPECT_EQ(LoadError(file), file.string() + ": rotation_search: missing");
}

}  // namespace
}  // namespace foresight
