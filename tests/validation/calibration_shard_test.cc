// Physics calibration in shards (validation/calibration_shard.h): shards written to JSON text,
// read back and merged give every kick's observations, draws and misses of the unsharded run,
// bit for bit and in trial order.
#include "validation/calibration_shard.h"

#include <gtest/gtest.h>

#include "tests/support/temp_files.h"

namespace foresight {
namespace {

PhysicsCalibrationSettings Nao() {
  PhysicsCalibrationSettings settings;
  settings.robot = "nao";
  settings.trials = 10;
  settings.seed = 5;
  settings.threads = 2;
  // The fixed base, the cheap approximation (a tenth of a floating trial's cost): shards
  // split the trials alike on both.
  settings.base = RobotBase::kFixed;
  return settings;
}

TEST(CalibrationShardTest, MergedShardsEqualTheWholeRun) {
  const PhysicsCalibration whole = RunPhysicsCalibration(Nao(), testing::ModelsDir());
  std::vector<ShardPart> parts;
  for (int i = 0; i < 3; ++i) {
    PhysicsCalibrationSettings settings = Nao();
    settings.shard = {i, 3};
    const PhysicsCalibration part = RunPhysicsCalibration(settings, testing::ModelsDir());
    ShardPart shard_part;
    shard_part.file = "shard" + settings.shard.Text();
    shard_part.header.shard = settings.shard;
    shard_part.header.items = settings.trials;
    shard_part.results =
        nlohmann::json::parse(CalibrationShardResults(part, settings.shard, settings.trials).dump());
    parts.push_back(shard_part);
  }
  PhysicsCalibration merged = PlanPhysicsCalibration(Nao(), testing::ModelsDir());
  MergeCalibrationShards(merged, Nao().trials, parts);
  ASSERT_EQ(merged.kicks.size(), whole.kicks.size());
  ASSERT_EQ(whole.kicks.size(), 3u);
  for (std::size_t j = 0; j < whole.kicks.size(); ++j) {
    const PhysicsKickTrials &a = merged.kicks[j], &b = whole.kicks[j];
    SCOPED_TRACE(b.kick);
    EXPECT_EQ(a.kick, b.kick);
    EXPECT_EQ(a.missed, b.missed);
    EXPECT_EQ(a.trials, b.trials);
    ASSERT_EQ(a.observations.size(), b.observations.size());
    EXPECT_EQ(static_cast<int>(b.observations.size()) + b.missed, 10);
    for (std::size_t i = 0; i < a.observations.size(); ++i) {
      const KickObservation &x = a.observations[i], &y = b.observations[i];
      EXPECT_EQ(x.launch_speed_mps, y.launch_speed_mps);
      EXPECT_EQ(x.launch_direction_rad, y.launch_direction_rad);
      EXPECT_EQ(x.has_roll_distance, y.has_roll_distance);
      EXPECT_EQ(x.roll_distance_m, y.roll_distance_m);
      ASSERT_EQ(x.rolling.size(), y.rolling.size());
      for (std::size_t s = 0; s < x.rolling.size(); ++s) {
        EXPECT_EQ(x.rolling[s].t_s, y.rolling[s].t_s);
        EXPECT_EQ(x.rolling[s].speed_mps, y.rolling[s].speed_mps);
      }
      EXPECT_EQ(a.draws[i].placement_dx_m, b.draws[i].placement_dx_m);
      EXPECT_EQ(a.draws[i].speed_factor, b.draws[i].speed_factor);
      EXPECT_EQ(a.draws[i].carpet_factor, b.draws[i].carpet_factor);
    }
  }
}

// A trial that fell, one whose stance was blocked and one that missed the ball each read back as
// what it was: blocked trials are not counted as missed (both stay out of the fit).
TEST(CalibrationShardTest, BlockedFallenAndMissedTrialsReadBackApart) {
  PhysicsCalibration run = PlanPhysicsCalibration(Nao(), testing::ModelsDir());
  ASSERT_EQ(run.kicks.size(), 3u);
  // No observation in this run: the first kick blocked in trials 1 and 4 and fell in 2; every
  // other trial of every kick missed.
  run.kicks[0].blocked = 2;
  run.kicks[0].blocked_trials = {1, 4};
  run.kicks[0].fell = 1;
  run.kicks[0].fell_trials = {2};
  const Shard whole{0, 1};
  ShardPart part;
  part.file = "shard";
  part.header.shard = whole;
  part.header.items = 6;
  part.results = nlohmann::json::parse(CalibrationShardResults(run, whole, 6).dump());
  PhysicsCalibration merged = PlanPhysicsCalibration(Nao(), testing::ModelsDir());
  MergeCalibrationShards(merged, 6, {part});
  EXPECT_EQ(merged.kicks[0].blocked, 2);
  EXPECT_EQ(merged.kicks[0].blocked_trials, (std::vector<int>{1, 4}));
  EXPECT_EQ(merged.kicks[0].fell, 1);
  EXPECT_EQ(merged.kicks[0].fell_trials, (std::vector<int>{2}));
  EXPECT_EQ(merged.kicks[0].missed, 3);
  EXPECT_EQ(merged.kicks[1].missed, 6);
  EXPECT_EQ(merged.kicks[1].blocked, 0);
  EXPECT_TRUE(merged.kicks[0].observations.empty());
}

TEST(CalibrationShardTest, AShardPlaysOnlyItsTrials) {
  PhysicsCalibrationSettings settings = Nao();
  settings.shard = {1, 4};  // trials 1, 5, 9
  const PhysicsCalibration part = RunPhysicsCalibration(settings, testing::ModelsDir());
  for (const PhysicsKickTrials& kick : part.kicks) {
    EXPECT_EQ(static_cast<int>(kick.observations.size()) + kick.missed, 3) << kick.kick;
    for (int trial : kick.trials) EXPECT_EQ(trial % 4, 1);
  }
}

}  // namespace
}  // namespace foresight
