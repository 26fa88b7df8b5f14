// The stability experiment in shards (experiments/stability_shard.h): shards written to JSON
// text, read back and merged give exactly the unsharded result.
#include "experiments/stability_shard.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

StabilityParams SmallParams() {
  StabilityParams p;
  p.situation = testing::MakeSituation({});
  p.strategy = Strategy::kNaoth;
  p.grid_step_m = 1.5;             // 6 x 4 positions
  p.heading_step_rad = kPi / 2.0;  // 4 headings: 96 poses
  p.repeats = 12;
  p.sample_counts = {1, 5, 30};
  p.map_samples = 30;
  p.rotation_bin_rad = 10.0 * kDegToRad;
  p.Validate();
  return p;
}

// Shard `shard` of a run, as `foresight merge` reads it: through the file's text.
ShardPart PartOf(const StabilityParams& params, const Shard& shard) {
  const StabilityResult result = RunStability(params, 7, 1, {}, shard);
  ShardPart part;
  part.file = "shard" + shard.Text();
  part.header.shard = shard;
  part.header.items = StabilityItems(params);
  part.results = nlohmann::json::parse(StabilityShardResults(result, shard).dump());
  return part;
}

TEST(StabilityShardTest, MergedShardsEqualTheWholeRun) {
  const StabilityParams params = SmallParams();
  const StabilityResult whole = RunStability(params, 7, 2);
  ASSERT_EQ(StabilityItems(params), 96);
  for (int count : {1, 3, 5}) {
    std::vector<ShardPart> parts;
    for (int i = 0; i < count; ++i) parts.push_back(PartOf(params, {i, count}));
    const StabilityResult merged = MergeStabilityShards(params, parts);
    EXPECT_EQ(merged.top_count, whole.top_count) << count << " shards";
    EXPECT_EQ(merged.distinct, whole.distinct);
    EXPECT_EQ(merged.decisions, whole.decisions);
    ASSERT_EQ(merged.counts.size(), whole.counts.size());
    for (std::size_t c = 0; c < whole.counts.size(); ++c) {
      EXPECT_EQ(merged.counts[c].share_above_80, whole.counts[c].share_above_80);
      EXPECT_EQ(merged.counts[c].mean_top_share, whole.counts[c].mean_top_share);
      EXPECT_EQ(merged.counts[c].mean_distinct, whole.counts[c].mean_distinct);
    }
  }
}

TEST(StabilityShardTest, AShardDecidesOnlyItsPoses) {
  const StabilityParams params = SmallParams();
  const StabilityResult part = RunStability(params, 7, 1, {}, {1, 4});
  EXPECT_TRUE(part.counts.empty());
  const int poses = part.grid.PoseCount();
  for (int p = 0; p < poses; ++p) EXPECT_EQ(part.top_count[p] > 0, p % 4 == 1) << p;
}

TEST(StabilityShardTest, AResultThatCannotBeACountIsRefused) {
  const StabilityParams params = SmallParams();
  ShardPart part = PartOf(params, {0, 1});
  part.results[3]["top"][1] = params.repeats + 1;
  try {
    MergeStabilityShards(params, {part});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "shard0/1: results[3].top[1]: not a count of 12 decisions");
  }
}

}  // namespace
}  // namespace foresight
