// The retrieval parameters: the shipped file is the paper's defaults; bad values name their field.
#include "cbr/retrieval_params.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "common/geometry.h"
#include "models/kick_model.h"
#include "tests/support/model_test_util.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

const FieldSpec& FourLegged() {
  static const FieldSpec field = LoadFieldSpec(testing::ModelsDir() / "fields/four_legged.json");
  return field;
}

TEST(RetrievalParamsTest, ShippedFileHoldsThePapersDefaults) {
  const RetrievalParams p =
      LoadRetrievalParams(testing::ModelsDir() / "cbr/retrieval.json", FourLegged());
  const RetrievalParams d;
  EXPECT_DOUBLE_EQ(p.thr_ball, std::exp(-1.0));
  EXPECT_DOUBLE_EQ(p.thr_ball, d.thr_ball);
  EXPECT_DOUBLE_EQ(p.thr_cost_m, 1.5);
  EXPECT_DOUBLE_EQ(p.thr_trajectory, d.thr_trajectory);
  EXPECT_DOUBLE_EQ(p.thr_opponent, d.thr_opponent);
  EXPECT_EQ(p.band_lower, (std::array<double, 3>{0.8, 0.6, 0.4}));
  EXPECT_EQ(p.cost, CostFunction::kSum);
  EXPECT_EQ(p.order, d.order);
  EXPECT_EQ(p.order[0], RankCriterion::kConditions);
  EXPECT_EQ(p.widths, TrajectoryWidths::kData);
  EXPECT_DOUBLE_EQ(p.default_kick.r_min_m, 0.1);
  EXPECT_DOUBLE_EQ(p.default_kick.r_max_m, 0.3);
  EXPECT_DOUBLE_EQ(p.goal_x_m, FourLegged().HalfLength());  // from the field, not the file
  EXPECT_DOUBLE_EQ(p.ball_radius_m, FourLegged().ball.radius_m);
  EXPECT_NO_THROW(d.Validate());
}

std::string Json(const std::string& cost, const std::string& order) {
  return R"({"thr_ball": 0.3, "thr_cost_m": 1.5, "thr_trajectory": 0.3, "thr_opponent": 0.3,
    "bands": {"H": 0.8, "h": 0.6, "l": 0.4}, "cost": ")" +
         cost + R"(", "order": )" + order +
         R"(, "widths": "data", "width_sigmas": 1, "default_kick": {"r_min_m": 0.1, "r_max_m": 0.3},
    "kicks": [{"kick": "forward", "r_min_m": 0.05, "r_max_m": 0.4, "reach_m": 2}]})";
}

TEST(RetrievalParamsTest, ReadsCostOrderAndKicks) {
  const auto file = testing::WriteTempFile(
      "retrieval_ok.json",
      Json("max_then_sum", R"(["band_then_cost", "teammates", "conditions"])"));
  const RetrievalParams p = LoadRetrievalParams(file, FourLegged());
  EXPECT_EQ(p.cost, CostFunction::kMaxThenSum);
  EXPECT_EQ(p.order[0], RankCriterion::kBandThenCost);
  EXPECT_EQ(p.order[2], RankCriterion::kConditions);
  EXPECT_DOUBLE_EQ(p.TrajectoryFor("forward").r_max_m, 0.4);
  EXPECT_DOUBLE_EQ(p.TrajectoryFor("forward").reach_m, 2.0);
  EXPECT_DOUBLE_EQ(p.TrajectoryFor("other").r_max_m, 0.3);
}

TEST(RetrievalParamsTest, BadValuesNameFileAndField) {
  const auto bad_cost = testing::WriteTempFile(
      "retrieval_bad_cost.json", Json("mean", R"(["conditions", "teammates", "band_then_cost"])"));
  try {
    LoadRetrievalParams(bad_cost, FourLegged());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("retrieval_bad_cost.json: cost: must be one of sum, max"));
  }
  const auto twice = testing::WriteTempFile(
      "retrieval_twice.json", Json("sum", R"(["conditions", "conditions", "band_then_cost"])"));
  try {
    LoadRetrievalParams(twice, FourLegged());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("retrieval_twice.json: order: "));
    EXPECT_THAT(e.what(), HasSubstr("conditions twice"));
  }
  RetrievalParams p;
  p.band_lower = {0.6, 0.8, 0.4};
  EXPECT_THROW(p.Validate(), InputError);
  p = RetrievalParams{};
  p.default_kick.r_min_m = 0.0;
  EXPECT_THROW(p.Validate(), InputError);
}

// A corridor wider than the field, a kick longer than its diagonal or a walk longer than it is a
// typing error whose arithmetic overflows: refused with the file and field (1e308 was accepted).
TEST(RetrievalParamsTest, WidthsReachAndCostBeyondTheFieldAreRefused) {
  const auto huge = testing::BrokenShipped("cbr/retrieval.json", "retrieval_huge",
                                           "\"r_max_m\": 0.3", "\"r_max_m\": 1e308");
  EXPECT_THAT(testing::InputErrorMessage([&] { LoadRetrievalParams(huge, FourLegged()); }),
              HasSubstr("retrieval_huge.json: default_kick.r_max_m: must be in [0, 3.6], got "));
  RetrievalParams p;
  p.default_kick.r_min_m = 3.7;  // the four-legged field is 3.6 m wide
  EXPECT_THROW(p.Validate(), InputError);
  p = RetrievalParams{};
  p.thr_cost_m = 6.6;  // its diagonal is 6.48 m
  EXPECT_THROW(p.Validate(), InputError);
  p = RetrievalParams{};
  p.default_kick.reach_m = 6.6;
  EXPECT_THROW(p.Validate(), InputError);
  p = RetrievalParams{};
  p.default_kick.r_max_m = 3.6;
  p.thr_cost_m = 6.4;
  EXPECT_NO_THROW(p.Validate());
}

TEST(RetrievalParamsTest, KickModelWidthsTakeEachKicksDirectionNoise) {
  KickModel model;
  model.kicks.push_back({"forward", 0.5, 0.1, 0.0, 7.0 * kDegToRad});
  model.kicks.push_back({"side", 0.5, 0.1, 1.5, 4.0 * kDegToRad});
  RetrievalParams p;
  p.kicks.push_back({"forward", 0.2, 0.5, 0.0, 0.0});
  UseKickModelWidths(model, &p);
  EXPECT_EQ(p.widths, TrajectoryWidths::kKickModel);
  ASSERT_EQ(p.kicks.size(), 2u);
  EXPECT_DOUBLE_EQ(p.TrajectoryFor("forward").sigma_direction_rad, 7.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(p.TrajectoryFor("forward").r_min_m, 0.2);  // kept
  EXPECT_DOUBLE_EQ(p.TrajectoryFor("side").sigma_direction_rad, 4.0 * kDegToRad);
  EXPECT_NO_THROW(p.Validate());
}

// A kick's trajectory is cut at its reach (the roll of a launch reach_sigmas sd strong) and a kick
// into the field runs on to its mean roll (cbr/free_path.h): v^2 / (2 a) at 0.5 m/s and 0.25 m/s^2
// is 0.5 m, at 0.5 + 2 x 0.1 m/s 0.98 m.
TEST(RetrievalParamsTest, KickModelReachIsTheRollTwoSdStrongAndRollTheMeanOne) {
  KickModel model;
  model.rolling_deceleration_mps2 = 0.25;
  model.kicks.push_back({"forward", 0.5, 0.1, 0.0, 7.0 * kDegToRad});
  RetrievalParams p;
  UseKickModelReach(model, &p);
  EXPECT_EQ(p.TrajectoryFor("forward").reach_m, 0.0);  // no reach_sigmas: the paper's paths
  p.reach_sigmas = 2.0;
  UseKickModelReach(model, &p);
  EXPECT_NEAR(p.TrajectoryFor("forward").reach_m, 0.98, 1e-12);
  EXPECT_NEAR(p.TrajectoryFor("forward").roll_m, 0.5, 1e-12);
}

TEST(RetrievalParamsTest, TheDefaultKickNamesNoKick) {
  std::string text = Json("sum", R"(["conditions", "teammates", "band_then_cost"])");
  const std::string from = R"("default_kick": {)";
  text.replace(text.find(from), from.size(), R"("default_kick": {"kick": "forward", )");
  const auto file = testing::WriteTempFile("retrieval_default_kick.json", text);
  try {
    LoadRetrievalParams(file, FourLegged());
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("default_kick.kick: unknown field"));
  }
}

}  // namespace
}  // namespace foresight
