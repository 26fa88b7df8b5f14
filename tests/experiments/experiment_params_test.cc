// The experiments' parameter files: the shipped ones hold the paper's defaults; bad files fail
// with a message naming the file, the field and the value.
#include "experiments/experiment_params.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "models/kick_model.h"
#include <unistd.h>

#include "common/error.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

std::filesystem::path Models() {
  return testing::ModelsDir();
}

std::string Unique(const std::string& name) {
  return name + "." + std::to_string(::getpid()) + ".json";
}

// The message of the InputError that `load` throws ("" if none).
template <typename Load>
std::string ErrorOf(Load load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kStability = R"({"situation": "experiment_nao", "strategy": "naoth",
  "grid_step_m": 0.3, "heading_step_deg": 5, "repeats": 100, "sample_counts": [1, 2, 30],
  "map_samples": 30, "rotation_bin_deg": 10})";

std::string StabilityErrorWith(const std::string& from, const std::string& to) {
  std::string text = kStability;
  text.replace(text.find(from), from.size(), to);
  const auto file = testing::WriteTempFile(Unique("stability_bad"), text);
  return ErrorOf([&] { LoadStabilityParams(file.string(), Models()); });
}

TEST(ExperimentParamsTest, ShippedStabilityIsThePapersGrid) {
  const StabilityParams p = LoadStabilityParams("stability", Models());
  EXPECT_DOUBLE_EQ(p.grid_step_m, 0.30);
  EXPECT_NEAR(p.heading_step_rad * kRadToDeg, 5.0, 1e-12);
  EXPECT_EQ(p.repeats, 100);
  std::vector<int> expected;
  for (int n = 1; n <= 25; ++n) expected.push_back(n);
  for (int n = 30; n <= 110; n += 10) expected.push_back(n);
  EXPECT_EQ(p.sample_counts, expected);
  EXPECT_EQ(p.map_samples, 30);
  EXPECT_EQ(p.situation.field.name, "spl");
  EXPECT_TRUE(p.situation.obstacles.empty());
}

TEST(ExperimentParamsTest, ShippedStrategiesAreThePapersSetting) {
  const StrategiesParams p = LoadStrategiesParams("strategies", Models());
  EXPECT_EQ(p.starts, 10000);
  EXPECT_DOUBLE_EQ(p.walk_speed_mps, 0.2);
  EXPECT_NEAR(p.turn_speed_radps * kRadToDeg, 60.0, 1e-12);
  EXPECT_NEAR(p.turn_around_ball_speed_radps * kRadToDeg, 30.0, 1e-12);
  EXPECT_EQ(p.strategies, (std::vector<Strategy>{Strategy::kFast, Strategy::kOptimalValue,
                                                 Strategy::kOptimalAll, Strategy::kOptimalOne}));
  EXPECT_EQ(p.situation.evaluation.samples, 30);
}

TEST(ExperimentParamsTest, KicksOverrideReplacesTheScenesKickModel) {
  const auto kicks = Models() / "kicks" / "nao_calibrated.json";
  SituationOverrides overrides;
  overrides.kicks_file = kicks;
  const StrategiesParams p = LoadStrategiesParams("strategies", Models(), overrides);
  EXPECT_EQ(p.situation.kicks_file, kicks);
  // The calibrated model's forward kick, not the paper's 1.08 m/s of the scene's own model.
  EXPECT_EQ(p.situation.kicks.kicks[0].speed_mps, LoadKickModel(kicks).kicks[0].speed_mps);
  EXPECT_NE(p.situation.kicks.kicks[0].speed_mps, 1.08);
}

TEST(ExperimentParamsTest, BadValuesNameFileFieldAndValue) {
  EXPECT_THAT(StabilityErrorWith("\"naoth\"", "\"greedy\""),
              HasSubstr("strategy: must be one of fast, optimal_value, optimal_all, optimal_one, "
                        "naoth, got 'greedy'"));
  EXPECT_THAT(StabilityErrorWith("[1, 2, 30]", "[1, 30, 2]"),
              HasSubstr("sample_counts: must be ascending without repeats, got 2 after 30"));
  EXPECT_THAT(StabilityErrorWith("\"map_samples\": 30", "\"map_samples\": 20"),
              HasSubstr("map_samples: must be one of sample_counts, got 20"));
  EXPECT_THAT(StabilityErrorWith("\"repeats\": 100", "\"repeats\": 2.5"),
              HasSubstr("repeats: must be a whole number, got 2.5"));
  const std::string step = StabilityErrorWith("\"grid_step_m\": 0.3", "\"grid_step_m\": 0");
  EXPECT_THAT(step, HasSubstr("stability_bad"));
  EXPECT_THAT(step, HasSubstr("grid_step_m: must be in [0.05, 3], got 0"));
  const std::string unknown = StabilityErrorWith("\"repeats\"", "\"repeat\"");
  EXPECT_THAT(unknown, HasSubstr("stability_bad"));
  EXPECT_THAT(unknown, HasSubstr("repeat"));
}

TEST(ExperimentParamsTest, StrategiesNeedAnEmptyField) {
  const auto file = testing::WriteTempFile(
      Unique("strategies_obstacle"),
      R"({"situation": ")" + (Models() / "situations" / "blocked_by_defender.json").string() +
          R"(", "strategies": ["fast"], "starts": 10, "max_steps": 10, "walk_speed_mps": 0.2,
          "turn_speed_deg_per_s": 60, "turn_around_ball_speed_deg_per_s": 30})");
  EXPECT_THAT(ErrorOf([&] { LoadStrategiesParams(file.string(), Models()); }),
              HasSubstr("situation: must have no obstacles"));
}

TEST(ExperimentParamsTest, MissingFileNamesIt) {
  EXPECT_THAT(ErrorOf([] { LoadStabilityParams("no_such_experiment", Models()); }),
              HasSubstr("no_such_experiment.json does not exist"));
}

TEST(ExperimentParamsTest, SampleCountListsParse) {
  EXPECT_EQ(ParseSampleCounts("--samples", "1-3,10,20-40/10"),
            (std::vector<int>{1, 2, 3, 10, 20, 30, 40}));
  EXPECT_EQ(ParseSampleCounts("--samples", "7"), (std::vector<int>{7}));
  for (const char* bad : {"", "a", "1-", "5-3", "1/2", "1-9/0", "1,,2", "3x", "1-2000000000",
                          "1-2147483647", "1-5000/1"}) {
    EXPECT_THAT(ErrorOf([&] { ParseSampleCounts("--samples", bad); }), HasSubstr("--samples: "))
        << bad;
  }
}

}  // namespace
}  // namespace foresight
