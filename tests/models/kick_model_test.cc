#include "models/kick_model.h"

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

constexpr const char* kForwardLine =
    R"({"name": "forward",         "speed_mps": 1.08, "sigma_speed_mps": 0.15, "direction_deg": 0.0,   "sigma_direction_deg": 7.0})";

std::filesystem::path BrokenNaoKicks(const std::string& name, const std::string& from,
                                     const std::string& to) {
  return BrokenShipped("kicks/nao.json", "kick_model_" + name, from, to);
}

std::string LoadError(const std::filesystem::path& file) {
  return InputErrorMessage([&] { LoadKickModel(file); });
}

KickModel ShippedNao() {
  return LoadKickModel(ModelsDir() / "kicks" / "nao.json");
}

TEST(KickModelTest, ShippedNaoModelHasThreeKicksInOrder) {
  const KickModel model = ShippedNao();
  EXPECT_EQ(model.robot, "nao");
  ASSERT_EQ(model.kicks.size(), 3u);
  EXPECT_EQ(model.kicks[0].name, "forward");
  EXPECT_EQ(model.kicks[1].name, "side_kick_left");
  EXPECT_EQ(model.kicks[2].name, "side_kick_right");
  // a = mu * g with mu = 0.0275.
  EXPECT_NEAR(model.rolling_deceleration_mps2, 0.0275 * 9.81, 1e-3);
}

TEST(KickModelTest, ForwardKickIs108MetresPerSecondStraightAhead) {
  const KickSpec k = ShippedNao().kicks[0];
  EXPECT_DOUBLE_EQ(k.speed_mps, 1.08);
  EXPECT_DOUBLE_EQ(k.sigma_speed_mps, 0.15);
  EXPECT_DOUBLE_EQ(k.direction_rad, 0.0);
  EXPECT_NEAR(k.sigma_direction_rad, 7.0 * kDegToRad, 1e-15);
}

TEST(KickModelTest, SideKicksGoSidewaysInRadians) {
  const KickModel model = ShippedNao();
  const KickSpec& left = model.kicks[1];
  const KickSpec& right = model.kicks[2];
  EXPECT_DOUBLE_EQ(left.speed_mps, 0.75);
  EXPECT_DOUBLE_EQ(left.sigma_speed_mps, 0.15);
  EXPECT_NEAR(left.direction_rad, kPi / 2.0, 1e-15);  // the loader converts degrees once
  EXPECT_NEAR(left.sigma_direction_rad, 10.0 * kDegToRad, 1e-15);
  EXPECT_DOUBLE_EQ(right.speed_mps, 0.75);
  EXPECT_DOUBLE_EQ(right.sigma_speed_mps, 0.15);
  EXPECT_NEAR(right.direction_rad, -kPi / 2.0, 1e-15);
  EXPECT_NEAR(right.sigma_direction_rad, 10.0 * kDegToRad, 1e-15);
}

TEST(KickModelTest, FindReturnsIndexOrNothing) {
  const KickModel model = ShippedNao();
  EXPECT_EQ(model.Find("forward"), 0);
  EXPECT_EQ(model.Find("side_kick_right"), 2);
  EXPECT_EQ(model.Find("none"), std::nullopt);
  EXPECT_EQ(model.Find("Forward"), std::nullopt);
}

TEST(KickModelTest, NegativeSpeedSigmaNamesKickFieldAndValue) {
  const auto file =
      BrokenNaoKicks("negative_sigma_speed", "\"sigma_speed_mps\": 0.15, \"direction_deg\": 0.0",
                     "\"sigma_speed_mps\": -0.15, \"direction_deg\": 0.0");
  EXPECT_EQ(LoadError(file),
            file.string() + ": kicks[0].sigma_speed_mps: must be in [0, 50], got -0.15");
}

TEST(KickModelTest, NegativeDirectionSigmaIsReportedInDegrees) {
  const auto file = BrokenNaoKicks("negative_sigma_dir",
                                   "\"direction_deg\": 90.0,  \"sigma_direction_deg\": 10.0",
                                   "\"direction_deg\": 90.0,  \"sigma_direction_deg\": -10.0");
  EXPECT_EQ(LoadError(file),
            file.string() + ": kicks[1].sigma_direction_deg: must be in [0, 180], got -10");
}

TEST(KickModelTest, DirectionBeyondHalfCircleIsRejected) {
  const auto file =
      BrokenNaoKicks("direction_270", "\"direction_deg\": -90.0", "\"direction_deg\": -270.0");
  EXPECT_EQ(LoadError(file),
            file.string() + ": kicks[2].direction_deg: must be in [-180, 180], got -270");
}

TEST(KickModelTest, DuplicateKickNameIsRejected) {
  const auto file =
      BrokenNaoKicks("duplicate", "\"name\": \"side_kick_left\"", "\"name\": \"forward\"");
  EXPECT_EQ(LoadError(file), file.string() + ": kicks[1].name: duplicate 'forward'");
}

TEST(KickModelTest, KickCalledNoneIsRejected) {
  const auto file = BrokenNaoKicks("none", "\"name\": \"side_kick_right\"", "\"name\": \"none\"");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": kicks[2].name: "));
  EXPECT_THAT(message, HasSubstr("'none'"));
}

TEST(KickModelTest, EmptyKickListIsRejected) {
  const std::string text = R"({"robot": "nao", "rolling_deceleration_mps2": 0.27, "kicks": []})";
  const auto file = WriteTempFile("kick_model_empty.json", text);
  EXPECT_EQ(LoadError(file), file.string() + ": kicks: must list at least one kick");
}

TEST(KickModelTest, TypoInKickFieldIsAnUnknownField) {
  const auto file = BrokenNaoKicks("typo", "\"sigma_speed_mps\": 0.15, \"direction_deg\": 90.0",
                                   "\"sigma_speed\": 0.15, \"direction_deg\": 90.0");
  EXPECT_EQ(LoadError(file), file.string() + ": kicks[1].sigma_speed: unknown field");
}

TEST(KickModelTest, SpeedGivenAsStringNamesTheValue) {
  const auto file = BrokenNaoKicks("type", "\"speed_mps\": 1.08", "\"speed_mps\": \"fast\"");
  EXPECT_EQ(LoadError(file),
            file.string() + ": kicks[0].speed_mps: must be a number, got \"fast\"");
}

TEST(KickModelTest, MissingDirectionIsNamed) {
  const auto file = BrokenNaoKicks("missing_direction", "\"direction_deg\": 0.0,   ", "");
  EXPECT_EQ(LoadError(file), file.string() + ": kicks[0].direction_deg: missing");
}

TEST(KickModelTest, ZeroRollingDecelerationIsRejected) {
  const auto file = BrokenNaoKicks("no_friction", "\"rolling_deceleration_mps2\": 0.2697",
                                   "\"rolling_deceleration_mps2\": 0");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": rolling_deceleration_mps2: must be in ["));
  EXPECT_THAT(message, HasSubstr("got 0"));
}

TEST(KickModelTest, InfiniteSigmaCannotEnter) {
  // nlohmann rejects 1e999 with json::out_of_range; the reader wraps it with line and key.
  const auto file = BrokenNaoKicks(
      "infinite_sigma", kForwardLine,
      R"({"name": "forward", "speed_mps": 1.08, "sigma_speed_mps": 1e999, "direction_deg": 0.0, "sigma_direction_deg": 7.0})");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, HasSubstr(file.string()));
  EXPECT_THAT(message, HasSubstr("sigma_speed_mps"));
}

TEST(KickModelTest, TheShippedPaperModelHasNoLaunchOffset) {
  for (const KickSpec& k : ShippedNao().kicks) EXPECT_EQ(k.launch_offset_m, 0.0) << k.name;
}

TEST(KickModelTest, NegativeLaunchOffsetIsRejected) {
  const auto file = BrokenNaoKicks(
      "offset", kForwardLine,
      R"({"name": "forward", "speed_mps": 1.08, "sigma_speed_mps": 0.15, "direction_deg": 0.0, "sigma_direction_deg": 7.0, "launch_offset_m": -0.05})");
  const std::string message = LoadError(file);
  EXPECT_THAT(message, StartsWith(file.string() + ": kicks[0].launch_offset_m: must be in [0"));
  EXPECT_THAT(message, HasSubstr("got -0.05"));
}

TEST(KickModelJsonTest, ALaunchOffsetIsWrittenOnlyWhenThereIsOne) {
  KickModel model = ShippedNao();
  EXPECT_EQ(KickModelJson(model, "").find("launch_offset_m"), std::string::npos);
  model.kicks[0].launch_offset_m = 0.07321;
  const std::string text = KickModelJson(model, "");
  const KickModel back = LoadKickModel(testing::WriteTempFile("kick_model_offset.json", text));
  EXPECT_DOUBLE_EQ(back.kicks[0].launch_offset_m, 0.0732);  // 0.1 mm
  EXPECT_EQ(back.kicks[1].launch_offset_m, 0.0);
}

TEST(KickModelJsonTest, AModelAboutToBeWrittenIsReadBackByTheKickModelReader) {
  KickModel model = ShippedNao();
  EXPECT_EQ(ParseKickModel(KickModelJson(model, ""), "m.json").kicks.size(), model.kicks.size());
  // A deceleration fitted from damaged data (a shard sample of 1e308) is refused, not written.
  model.rolling_deceleration_mps2 = 1e63;
  EXPECT_THAT(InputErrorMessage([&] { ParseKickModel(KickModelJson(model, ""), "m.json"); }),
              StartsWith("m.json: rolling_deceleration_mps2: "));
}

TEST(KickModelJsonTest, WrittenModelLoadsBackWithRoundedNumbers) {
  KickModel model;
  model.robot = "nao";
  model.rolling_deceleration_mps2 = 0.271234;
  model.kicks.push_back({"forward", 0.781249, 0.0612, 1.23456 * kDegToRad, 4.5 * kDegToRad});
  model.kicks.push_back({"side \"left\"", 0.5, 0.02, 90.0 * kDegToRad, 3.0 * kDegToRad});
  const std::string text = KickModelJson(model, "calibrated: seed 7");
  const KickModel back = LoadKickModel(testing::WriteTempFile("kick_model_json_round.json", text));
  EXPECT_EQ(back.robot, "nao");
  EXPECT_DOUBLE_EQ(back.rolling_deceleration_mps2, 0.2712);
  ASSERT_EQ(back.kicks.size(), 2u);
  EXPECT_DOUBLE_EQ(back.kicks[0].speed_mps, 0.7812);
  EXPECT_DOUBLE_EQ(back.kicks[0].sigma_speed_mps, 0.0612);
  EXPECT_NEAR(back.kicks[0].direction_rad * kRadToDeg, 1.23, 1e-12);
  EXPECT_EQ(back.kicks[1].name, "side \"left\"");
  EXPECT_NEAR(back.kicks[1].direction_rad * kRadToDeg, 90.0, 1e-12);
  EXPECT_NE(text.find("\"notes\": \"calibrated: seed 7\""), std::string::npos);
}

TEST(KickModelJsonTest, ShippedModelSurvivesARoundTrip) {
  const KickModel shipped = ShippedNao();
  const KickModel back = LoadKickModel(
      testing::WriteTempFile("kick_model_json_shipped.json", KickModelJson(shipped, "")));
  ASSERT_EQ(back.kicks.size(), shipped.kicks.size());
  for (std::size_t i = 0; i < shipped.kicks.size(); ++i) {
    EXPECT_EQ(back.kicks[i].name, shipped.kicks[i].name);
    EXPECT_NEAR(back.kicks[i].speed_mps, shipped.kicks[i].speed_mps, 1e-12);
    EXPECT_NEAR(back.kicks[i].sigma_direction_rad, shipped.kicks[i].sigma_direction_rad, 1e-12);
  }
}

}  // namespace
}  // namespace foresight
