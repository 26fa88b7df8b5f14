// The typed kinds of `foresight check`: their names, their range checks, and running a check
// built in code rather than read from a file.
#include "validation/check_kinds.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

std::string ValidateError(const CheckKind& kind) {
  try {
    std::visit([](const auto& check) { check.Validate(); }, kind);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CheckKindsTest, KindNamesAreTheSpecsWords) {
  EXPECT_EQ(KindName(FreeRollCheck{}), "free_roll");
  EXPECT_EQ(KindName(NoTunnellingCheck{}), "no_tunnelling");
  EXPECT_EQ(KindName(KickDirectionCheck{}), "kick_direction");
  EXPECT_EQ(KindName(CalibrationBandCheck{}), "calibration_band");
  EXPECT_EQ(KindName(FidelityFloorCheck{}), "fidelity_floor");
  EXPECT_EQ(KindName(ReboundCheck{}), "rebound");
  EXPECT_EQ(KindName(RobotReboundCheck{}), "robot_rebound");
  EXPECT_EQ(ImpactTargetName(ImpactTarget::kPost), "post");
  EXPECT_EQ(ImpactTargetName(ImpactTarget::kBackNet), "back_net");
  EXPECT_EQ(ImpactTargetName(ImpactTarget::kSideNet), "side_net");
}

TEST(CheckKindsTest, ValidateNamesTheFieldAndTheValue) {
  FreeRollCheck roll;
  roll.speed_mps = -1.0;
  EXPECT_EQ(ValidateError(roll), "speed_mps: must be in [0.05, 20], got -1");
  roll.speed_mps = 1.0;
  roll.heading_deg = 1e308;
  EXPECT_EQ(ValidateError(roll), "heading_deg: must be in [-360, 360], got 1e+308");
  KickDirectionCheck direction;
  direction.trials = 1;
  EXPECT_EQ(ValidateError(direction), "trials: must be in [2, 100000], got 1");
  direction.trials = 30;
  EXPECT_EQ(ValidateError(direction), "no error");
  CalibrationBandCheck band;
  band.trials = 10;
  band.seed = (1ULL << 53) + 2;
  EXPECT_THAT(ValidateError(band), HasSubstr("seed: must be in [0, "));
}

TEST(CheckKindsTest, RunsACheckBuiltInCode) {
  NoTunnellingCheck post;
  post.field = "spl";
  post.target = ImpactTarget::kPost;
  post.speed_mps = 10.0;
  post.phases = 3;
  post.max_penetration_steps = 1.2;
  CheckSpec spec;
  spec.name = "post";
  spec.kind = post;
  spec.where = "test";
  const CheckResult r = RunCheck(spec, testing::ModelsDir(), 1);
  EXPECT_TRUE(r.passed) << r.detail;
  EXPECT_THAT(r.detail, HasSubstr("into the post"));
}

}  // namespace
}  // namespace foresight
