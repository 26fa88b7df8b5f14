#include "models/kick_motion.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "common/geometry.h"
#include "tests/support/model_test_util.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorMessage;
using testing::ReplaceOnce;
using ::testing::StartsWith;
using testing::WriteTempFile;

constexpr const char* kMotion = R"({
  "name": "forward",
  "notes": "a test motion",
  "ball_x_m": 0.17,
  "ball_y_m": -0.05,
  "joints": ["RHipPitch", "RKneePitch"],
  "keyframes": [
    {"time_s": 0.0, "positions_deg": [-25.0, 50.0]},
    {"time_s": 0.3, "positions_deg": [-40.0, 90.0]},
    {"time_s": 0.45, "positions_deg": [-60.0, 10.0]},
    {"time_s": 0.8, "positions_deg": [-25.0, 50.0]}
  ]
})";

std::filesystem::path MotionFile(const std::string& name, const std::string& from = "",
                                 const std::string& to = "") {
  const std::string text = from.empty() ? kMotion : ReplaceOnce(kMotion, from, to);
  return WriteTempFile("kick_motion_" + name + ".json", text);
}

std::string LoadError(const std::filesystem::path& file) {
  return InputErrorMessage([&] { LoadKickMotion(file); });
}

// A one-joint motion through `positions` at `times`.
KickMotion OneJoint(const std::vector<double>& times, const std::vector<double>& positions) {
  KickMotion motion;
  motion.name = "test";
  motion.joints = {"J"};
  for (std::size_t k = 0; k < times.size(); ++k) {
    motion.keyframes.push_back({times[k], {positions[k]}});
  }
  motion.Validate("inline");
  return motion;
}

struct Target {
  double q = 0.0, qdot = 0.0;
};

Target SampleOne(const KickMotion& motion, double t_s) {
  Target target;
  motion.Sample(t_s, std::span<double>(&target.q, 1), std::span<double>(&target.qdot, 1));
  return target;
}

TEST(KickMotionTest, LoadsNameBallJointsAndKeyframesInRadians) {
  const KickMotion motion = LoadKickMotion(MotionFile("load"));
  EXPECT_EQ(motion.name, "forward");
  EXPECT_EQ(motion.p_R_ball, Vec2(0.17, -0.05));
  EXPECT_EQ(motion.joints, (std::vector<std::string>{"RHipPitch", "RKneePitch"}));
  ASSERT_EQ(motion.keyframes.size(), 4u);
  EXPECT_EQ(motion.keyframes[2].time_s, 0.45);
  ASSERT_EQ(motion.keyframes[2].positions_rad.size(), 2u);
  EXPECT_DOUBLE_EQ(motion.keyframes[2].positions_rad[0], -60.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(motion.keyframes[2].positions_rad[1], 10.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(motion.DurationS(), 0.8);
}

TEST(KickMotionTest, SamplePassesThroughEveryKeyframeExactly) {
  const KickMotion motion = LoadKickMotion(MotionFile("through"));
  std::vector<double> q(2), qdot(2);
  for (const KickKeyframe& key : motion.keyframes) {
    motion.Sample(key.time_s, q, qdot);
    EXPECT_EQ(q[0], key.positions_rad[0]) << "t = " << key.time_s;
    EXPECT_EQ(q[1], key.positions_rad[1]) << "t = " << key.time_s;
  }
}

TEST(KickMotionTest, InteriorKeyframeVelocityIsTheCatmullRomTangent) {
  const KickMotion motion = LoadKickMotion(MotionFile("tangent"));
  std::vector<double> q(2), qdot(2);
  motion.Sample(0.3, q, qdot);
  // m_1 = (p_2 - p_0) / (t_2 - t_0).
  EXPECT_NEAR(qdot[0], (-60.0 - -25.0) * kDegToRad / 0.45, 1e-12);
  EXPECT_NEAR(qdot[1], (10.0 - 50.0) * kDegToRad / 0.45, 1e-12);
}

TEST(KickMotionTest, VelocityIsZeroAtBothEndsAndOutside) {
  const KickMotion motion = LoadKickMotion(MotionFile("ends"));
  std::vector<double> q(2), qdot(2);
  for (double t : {-1.0, 0.0, 0.8, 5.0}) {
    motion.Sample(t, q, qdot);
    EXPECT_EQ(qdot[0], 0.0) << "t = " << t;
    EXPECT_EQ(qdot[1], 0.0) << "t = " << t;
  }
  // Just inside the ends the velocity is small but not zero (zero tangent, quadratic start).
  motion.Sample(1e-3, q, qdot);
  EXPECT_NE(qdot[0], 0.0);
  EXPECT_LT(std::abs(qdot[0]), 0.05);
}

TEST(KickMotionTest, TimeIsClampedToTheMotion) {
  const KickMotion motion = LoadKickMotion(MotionFile("clamp"));
  std::vector<double> q(2), qdot(2);
  motion.Sample(-0.5, q, qdot);
  EXPECT_EQ(q[0], motion.keyframes.front().positions_rad[0]);
  motion.Sample(10.0, q, qdot);
  EXPECT_EQ(q[1], motion.keyframes.back().positions_rad[1]);
}

TEST(KickMotionTest, VelocityIsTheDerivativeOfPosition) {
  const KickMotion motion = LoadKickMotion(MotionFile("derivative"));
  std::vector<double> q_minus(2), q_plus(2), q(2), qdot(2), unused(2);
  const double h = 1e-6;
  for (double t = 0.01; t < 0.8; t += 0.0137) {
    motion.Sample(t, q, qdot);
    motion.Sample(t - h, q_minus, unused);
    motion.Sample(t + h, q_plus, unused);
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(qdot[j], (q_plus[j] - q_minus[j]) / (2.0 * h), 1e-6) << "t = " << t;
    }
  }
}

TEST(KickMotionTest, PositionAndVelocityAreContinuousAtKeyframes) {
  const KickMotion motion = LoadKickMotion(MotionFile("c1"));
  std::vector<double> before(2), after(2), v_before(2), v_after(2);
  const double h = 1e-9;
  for (std::size_t k = 1; k + 1 < motion.keyframes.size(); ++k) {
    const double t = motion.keyframes[k].time_s;
    motion.Sample(t - h, before, v_before);
    motion.Sample(t + h, after, v_after);
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(before[j], after[j], 1e-7) << "keyframe " << k;
      EXPECT_NEAR(v_before[j], v_after[j], 1e-6) << "keyframe " << k;
    }
  }
}

TEST(KickMotionTest, ThreeKeyframeRampHasTheRampsSlopeInTheMiddle) {
  // 0 -> 1 -> 2 rad at 0, 1, 2 s: m_1 = 1 rad/s; the ends start and stop at rest, and the
  // curve is point-symmetric about the middle keyframe.
  const KickMotion ramp = OneJoint({0.0, 1.0, 2.0}, {0.0, 1.0, 2.0});
  EXPECT_DOUBLE_EQ(SampleOne(ramp, 1.0).qdot, 1.0);
  EXPECT_DOUBLE_EQ(SampleOne(ramp, 1.0).q, 1.0);
  for (double t : {0.1, 0.35, 0.8}) {
    EXPECT_NEAR(SampleOne(ramp, t).q + SampleOne(ramp, 2.0 - t).q, 2.0, 1e-12) << t;
    EXPECT_NEAR(SampleOne(ramp, t).qdot, SampleOne(ramp, 2.0 - t).qdot, 1e-12) << t;
  }
  // On [0, 1] (m0 = 0, m1 = 1): q = h01 + h11 = -s^3 + 2 s^2, 0.375 at s = 0.5.
  EXPECT_NEAR(SampleOne(ramp, 0.5).q, 0.375, 1e-15);
}

TEST(KickMotionTest, EquallySpacedRampIsLinearBetweenInteriorKeyframes) {
  // With four keyframes on a line, both tangents of the middle segment equal the slope, and the
  // Hermite cubic reproduces the line exactly there: constant velocity 0.5 rad/s.
  const KickMotion ramp = OneJoint({0.0, 1.0, 2.0, 3.0}, {0.0, 0.5, 1.0, 1.5});
  for (double t = 1.0; t <= 2.0; t += 0.125) {
    EXPECT_NEAR(SampleOne(ramp, t).q, 0.5 * t, 1e-15) << t;
    EXPECT_NEAR(SampleOne(ramp, t).qdot, 0.5, 1e-14) << t;
  }
  // Before it, starting from rest, the velocity overshoots the slope: q = (-s^3 + 2 s^2) / 2,
  // qdot = (-3 s^2 + 4 s) / 2 = 0.625 at s = 0.5. (Catmull-Rom is not monotone.)
  EXPECT_NEAR(SampleOne(ramp, 0.5).qdot, 0.625, 1e-15);
}

TEST(KickMotionTest, UnequalSpacingUsesTheNonUniformTangent) {
  const KickMotion motion = OneJoint({0.0, 0.1, 1.0}, {0.0, 1.0, 0.0});
  EXPECT_DOUBLE_EQ(SampleOne(motion, 0.1).qdot, 0.0);  // (0 - 0) / (1 - 0)
  const KickMotion skew = OneJoint({0.0, 0.1, 1.0}, {0.0, 1.0, 3.0});
  EXPECT_DOUBLE_EQ(SampleOne(skew, 0.1).qdot, 3.0);  // (3 - 0) / (1 - 0)
}

TEST(KickMotionTest, TwoKeyframesGiveASmoothStep) {
  // q(s) = 3 s^2 - 2 s^3 between the two positions.
  const KickMotion step = OneJoint({0.0, 2.0}, {1.0, 3.0});
  EXPECT_NEAR(SampleOne(step, 1.0).q, 2.0, 1e-15);
  EXPECT_NEAR(SampleOne(step, 1.0).qdot, 1.5, 1e-15);  // 2 * 6 s (1 - s) / 2 at s = 1/2
  EXPECT_NEAR(SampleOne(step, 0.5).q, 1.0 + 2.0 * (3.0 / 16.0 - 2.0 / 64.0), 1e-15);
}

TEST(KickMotionTest, LoadsItsOwnStance) {
  const KickMotion plain = LoadKickMotion(MotionFile("no_stance"));
  EXPECT_FALSE(plain.stance.IsOwn());
  const KickMotion motion = LoadKickMotion(MotionFile(
      "stance", R"("ball_x_m": 0.17,)",
      R"("stance": {"base_height_m": 0.12, "pose_deg": {"notes": "up", "LKneePitch": 30.0}},
         "ball_x_m": 0.17,)"));
  EXPECT_TRUE(motion.stance.IsOwn());
  EXPECT_EQ(motion.stance.base_height_m, 0.12);
  ASSERT_EQ(motion.stance.pose_rad.size(), 1u);
  EXPECT_EQ(motion.stance.pose_rad[0].first, "LKneePitch");
  EXPECT_DOUBLE_EQ(motion.stance.pose_rad[0].second, 30.0 * kDegToRad);
}

TEST(KickMotionTest, AStanceNeedsAPositiveHeightAndOnlyItsFields) {
  const auto low = MotionFile("stance_height", R"("ball_x_m": 0.17,)",
                              R"("stance": {"base_height_m": 0, "pose_deg": {}}, "ball_x_m": 0.17,)");
  EXPECT_EQ(LoadError(low), low.string() + ": stance.base_height_m: must be in (0, 10], got 0");
  const auto high = MotionFile(
      "stance_too_high", R"("ball_x_m": 0.17,)",
      R"("stance": {"base_height_m": 1e308, "pose_deg": {}}, "ball_x_m": 0.17,)");
  EXPECT_THAT(LoadError(high), HasSubstr("stance.base_height_m: must be in (0, 10], got 1e+308"));
  const auto extra =
      MotionFile("stance_extra", R"("ball_x_m": 0.17,)",
                 R"("stance": {"base_height_m": 0.1, "pose_deg": {}, "tilt": 1}, "ball_x_m": 0.17,)");
  EXPECT_THAT(LoadError(extra), StartsWith(extra.string() + ": stance.tilt: "));
}

TEST(KickMotionTest, TheBallLiesWithinARobotsLengthOfIt) {
  for (const std::string& value : {"1e308", "-11", "10.5"}) {
    const auto file = MotionFile("far_ball", R"("ball_x_m": 0.17,)", "\"ball_x_m\": " + value + ",");
    EXPECT_THAT(LoadError(file), HasSubstr(file.string() + ": ball_x_m: must be within 10 m of "
                                           "the robot, got "))
        << value;
  }
}

TEST(KickMotionTest, LoadsItsBalanceAndRampsItSmoothly) {
  const KickMotion plain = LoadKickMotion(MotionFile("no_balance"));
  EXPECT_FALSE(plain.balance.Has());
  EXPECT_EQ(plain.balance.Share(5.0), 0.0);
  const KickMotion motion = LoadKickMotion(MotionFile(
      "balance", R"("ball_x_m": 0.17,)",
      R"("balance": {"shift_s": 2.0, "settle_s": 0.5,
                     "offsets_deg": {"notes": "why", "LHipRoll": -16.0, "LAnkleRoll": 16.0}},
         "ball_x_m": 0.17,)"));
  ASSERT_TRUE(motion.balance.Has());
  EXPECT_EQ(motion.balance.DurationS(), 2.5);
  ASSERT_EQ(motion.balance.offsets_rad.size(), 2u);
  for (const auto& [joint, offset_rad] : motion.balance.offsets_rad) {
    EXPECT_DOUBLE_EQ(offset_rad, (joint == "LHipRoll" ? -16.0 : 16.0) * kDegToRad) << joint;
  }
  // 3u^2 - 2u^3: 0 before, half way at half the shift, whole after it.
  EXPECT_EQ(motion.balance.Share(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(motion.balance.Share(1.0), 0.5);
  EXPECT_DOUBLE_EQ(motion.balance.Share(0.5), 3.0 / 16.0 - 2.0 / 64.0);
  EXPECT_EQ(motion.balance.Share(2.0), 1.0);
  EXPECT_EQ(motion.balance.Share(9.0), 1.0);
}

TEST(KickMotionTest, ABalanceNeedsATimeAndAJoint) {
  const auto no_time = MotionFile(
      "balance_time", R"("ball_x_m": 0.17,)",
      R"("balance": {"shift_s": 0, "settle_s": 0.5, "offsets_deg": {"J": 1}}, "ball_x_m": 0.17,)");
  EXPECT_EQ(LoadError(no_time), no_time.string() + ": balance.shift_s: must be in (0, 10], got 0");
  const auto no_joint = MotionFile(
      "balance_joint", R"("ball_x_m": 0.17,)",
      R"("balance": {"shift_s": 1, "settle_s": 0.5, "offsets_deg": {}}, "ball_x_m": 0.17,)");
  EXPECT_EQ(LoadError(no_joint),
            no_joint.string() + ": balance.offsets_deg: must name at least one joint");
}

TEST(KickMotionTest, SingleKeyframeIsRejected) {
  const auto file = WriteTempFile("kick_motion_single.json", R"({
    "name": "x", "ball_x_m": 0.1, "ball_y_m": 0.0, "joints": ["A"],
    "keyframes": [{"time_s": 0.0, "positions_deg": [1.0]}]})");
  EXPECT_EQ(LoadError(file), file.string() + ": keyframes: must list at least 2 keyframes, got 1");
}

TEST(KickMotionTest, MissingKeyframesAreNamed) {
  const auto file = WriteTempFile("kick_motion_no_keyframes.json",
                                  R"({"name": "x", "ball_x_m": 0.1, "ball_y_m": 0.0,
                                      "joints": ["A"]})");
  EXPECT_EQ(LoadError(file), file.string() + ": keyframes: missing");
}

TEST(KickMotionTest, FirstKeyframeMustBeAtZero) {
  const auto file = MotionFile("late_start", R"("time_s": 0.0,)", R"("time_s": 0.05,)");
  EXPECT_EQ(LoadError(file), file.string() + ": keyframes[0].time_s: must be 0, got 0.05");
}

TEST(KickMotionTest, TimesMustIncreaseStrictly) {
  const auto file = MotionFile("same_time", R"("time_s": 0.45,)", R"("time_s": 0.3,)");
  EXPECT_EQ(LoadError(file),
            file.string() +
                ": keyframes[2].time_s: must be greater than the previous keyframe's 0.3, got 0.3");
}

// A keyframe 10^5 times its time made each trial run for 35 s: a motion lasts at most the
// longest kick phase a physics file may time.
TEST(KickMotionTest, AMotionLastsNoLongerThanTheLongestKickPhase) {
  const auto file = MotionFile("endless", R"("time_s": 0.8,)", R"("time_s": 80000.0,)");
  EXPECT_EQ(LoadError(file), file.string() +
                                 ": keyframes[3].time_s: must be at most 60 s (the longest kick "
                                 "phase a physics file's steps.max_kick_time_s may time), got "
                                 "80000");
  EXPECT_NO_THROW(LoadKickMotion(MotionFile("minute", R"("time_s": 0.8,)", R"("time_s": 60.0,)")));
}

TEST(KickMotionTest, EachKeyframeHasOnePositionPerJoint) {
  const auto file = MotionFile("short_keyframe", "[-40.0, 90.0]", "[-40.0]");
  EXPECT_EQ(
      LoadError(file),
      file.string() + ": keyframes[1].positions_deg: must have 2 entries (one per joint), got 1");
}

TEST(KickMotionTest, PositionOfWrongTypeNamesItsIndex) {
  const auto file = MotionFile("string_position", "[-60.0, 10.0]", "[-60.0, \"ten\"]");
  EXPECT_EQ(LoadError(file),
            file.string() + ": keyframes[2].positions_deg[1]: must be a number, got \"ten\"");
}

TEST(KickMotionTest, JointNamesMustBeUnique) {
  const auto file = MotionFile("duplicate_joint", R"(["RHipPitch", "RKneePitch"])",
                               R"(["RHipPitch", "RHipPitch"])");
  EXPECT_EQ(LoadError(file), file.string() + ": joints[1]: duplicate 'RHipPitch'");
}

TEST(KickMotionTest, JointNamesMustBeNonEmptyStrings) {
  const auto empty = MotionFile("empty_joint", R"("RKneePitch"])", R"(""])");
  EXPECT_EQ(LoadError(empty), empty.string() + ": joints[1]: must be a non-empty joint name");
  const auto number = MotionFile("number_joint", R"("RKneePitch"])", R"(7])");
  EXPECT_EQ(LoadError(number), number.string() + ": joints[1]: must be a string, got 7");
}

TEST(KickMotionTest, MotionWithoutJointsIsRejected) {
  const auto file = WriteTempFile("kick_motion_no_joints.json", R"({
    "name": "x", "ball_x_m": 0.1, "ball_y_m": 0.0, "joints": [],
    "keyframes": [{"time_s": 0.0, "positions_deg": []}, {"time_s": 1.0, "positions_deg": []}]})");
  EXPECT_EQ(LoadError(file), file.string() + ": joints: must list at least one joint");
}

TEST(KickMotionTest, UnknownFieldsAreRejectedAtBothLevels) {
  const auto top = MotionFile("typo_top", "\"ball_y_m\"", "\"ball_z_m\"");
  EXPECT_EQ(LoadError(top), top.string() + ": ball_z_m: unknown field");
  const auto inner = MotionFile("typo_keyframe", R"({"time_s": 0.3, "positions_deg")",
                                R"({"time": 0.3, "positions_deg")");
  EXPECT_EQ(LoadError(inner), inner.string() + ": keyframes[1].time: unknown field");
}

TEST(KickMotionTest, JointsMustBeAnArray) {
  const auto file = MotionFile("joints_string", R"(["RHipPitch", "RKneePitch"])", R"("RHipPitch")");
  EXPECT_EQ(LoadError(file), file.string() + ": joints: must be an array, got \"RHipPitch\"");
}

TEST(KickMotionTest, ValidateRejectsNonFiniteValuesMadeInCode) {
  KickMotion motion = OneJoint({0.0, 1.0}, {0.0, 1.0});
  motion.keyframes[1].positions_rad[0] = std::nan("");
  EXPECT_EQ(InputErrorMessage([&] { motion.Validate("code"); }),
            "code: keyframes[1].positions_deg[0]: must be finite, got nan");
  motion.keyframes[1].positions_rad[0] = 1.0;
  motion.p_R_ball.y() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(InputErrorMessage([&] { motion.Validate("code"); }),
            "code: ball_y_m: must be within 10 m of the robot, got inf");
}

TEST(KickMotionTest, MissingFileIsNamed) {
  const std::filesystem::path file = testing::ModelsDir() / "robots" / "no_such_motion.json";
  EXPECT_THAT(LoadError(file), HasSubstr(file.string() + ": cannot open file"));
}

}  // namespace
}  // namespace foresight
