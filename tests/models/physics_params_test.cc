#include "models/physics_params.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/model_test_util.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorMessage;

PhysicsParams Shipped(const std::string& field) {
  return LoadPhysicsParams(testing::ModelsDir() / "physics" / (field + ".json"));
}

TEST(PhysicsParamsTest, ShippedFilesLoadAndAgreeWithTheKickModelsBelief) {
  for (const char* field : {"spl", "four_legged"}) {
    const PhysicsParams p = Shipped(field);
    // The carpet physics rolls on is what the shipped coarse model assumes (mu g, mu = 0.0275).
    EXPECT_DOUBLE_EQ(p.carpet.rolling_deceleration_mps2, 0.2697) << field;
    EXPECT_LT(p.steps.near_time_step_s, p.steps.free_time_step_s) << field;
  }
}

struct BrokenCase {
  const char* from;
  const char* to;
  const char* message;
};

class PhysicsParamsErrorTest : public ::testing::TestWithParam<BrokenCase> {};

TEST_P(PhysicsParamsErrorTest, NamesTheFileTheFieldAndTheValue) {
  const BrokenCase c = GetParam();
  // One file per case: ctest runs the cases in parallel processes sharing the temp folder.
  const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const auto file = testing::BrokenShipped(
      "physics/spl.json", "physics_broken_" + name.substr(name.rfind('/') + 1), c.from, c.to);
  const std::string message = InputErrorMessage([&] { LoadPhysicsParams(file); });
  EXPECT_THAT(message, HasSubstr(file.string()));
  EXPECT_THAT(message, HasSubstr(c.message));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, PhysicsParamsErrorTest,
    ::testing::Values(
        BrokenCase{"\"rolling_deceleration_mps2\": 0.2697", "\"rolling_deceleration_mps2\": -1",
                   "carpet.rolling_deceleration_mps2: must be in [0.001, 10], got -1"},
        BrokenCase{"\"free_time_step_s\": 0.016", "\"free_time_step_s\": 0.001",
                   "steps.free_time_step_s"},
        BrokenCase{"\"position_gain\": 0.2", "\"position_gain\": 2",
                   "motors.position_gain: must be in [0, 1], got 2"},
        BrokenCase{"\"ball_net\": 0.8", "\"ball_nett\": 0.8", "friction.ball_nett: unknown field"},
        BrokenCase{"\"ball_post\": 0.3,", "\"ball_post\": 1.3,",
                   "materials.restitution.ball_post: must be in [0, 1], got 1.3"},
        BrokenCase{"\"ball_net\": \"assumption: a slack net absorbs the ball (3 %)\"",
                   "\"ball_net\": \"\"", "restitution.sources.ball_net: must say where"},
        BrokenCase{"\"patch_seed\": 2026", "\"patch_seed\": -4", "carpet.patch_seed"},
        BrokenCase{"\"min_launch_roll_m\": 0.05", "\"min_launch_roll_m\": 2",
                   "steps.min_launch_roll_m: must be in [0, 0.5], got 2"},
        BrokenCase{"\"base\": \"floating\"", "\"base\": \"bolted\"",
                   "robot.base: must be one of fixed, floating, got 'bolted'"},
        BrokenCase{"\"fall_tilt_deg\": 45.0", "\"fall_tilt_deg\": 120",
                   "robot.fall_tilt_deg: must be in [1, 90], got 120"},
        BrokenCase{"\"restitution\": \"assumption: a rubber sole on turf over felt does not bounce\"",
                   "\"restitution\": \"\"",
                   "robot.sources.restitution: must say where"},
        BrokenCase{"\"still_time_s\": 0.1", "\"still_time_s\": 0",
                   "watch.still_time_s: must be in [0.01, 10], got 0"},
        BrokenCase{"\"still_tilt_deg\": 15.0", "\"still_tilt_deg\": 60",
                   "watch.still_tilt_rad"},
        BrokenCase{"\"still_base_speed_mps\": 0.005,", "\"still_base_speed_mps\": 0.005, \"x\": 1,",
                   "watch.x: unknown field"},
        BrokenCase{"\"still_time_s\": \"assumption: 50", "\"still_time_x\": \"assumption: 50",
                   "watch.sources.still_time_x: unknown field"}));

}  // namespace
}  // namespace foresight
