// Shards of a run (common/shard.h): every item in exactly one shard, and the flag's parser.
#include "common/shard.h"

#include <gtest/gtest.h>

#include <vector>

#include "common/error.h"

namespace foresight {
namespace {

TEST(ShardTest, EveryItemBelongsToExactlyOneShard) {
  for (int items : {0, 1, 5, 24, 101}) {
    for (int count : {1, 2, 3, 4, 7, 30}) {
      std::vector<int> owners(static_cast<std::size_t>(items), 0);
      for (int index = 0; index < count; ++index) {
        const Shard shard{index, count};
        const int owned = shard.OwnedCount(items);
        for (int k = 0; k < owned; ++k) {
          const int item = shard.Item(k);
          ASSERT_GE(item, 0);
          ASSERT_LT(item, items);
          EXPECT_TRUE(shard.Owns(item));
          ++owners[item];
        }
      }
      for (int n : owners) EXPECT_EQ(n, 1) << items << " items, " << count << " shards";
    }
  }
}

TEST(ShardTest, FromAnItemOnOwnsTheSameItems) {
  for (int count : {1, 2, 3, 7}) {
    for (int index = 0; index < count; ++index) {
      const Shard shard{index, count};
      for (int first : {0, 1, 5, 12, 100}) {
        const Shard from = shard.From(first);
        EXPECT_EQ(from.count, count);
        for (int j = 0; j < 30; ++j) EXPECT_EQ(from.Owns(j), shard.Owns(first + j)) << first + j;
      }
    }
  }
}

TEST(ShardTest, ParsesIndexOverCount) {
  const Shard s = ParseShard("--shard", "3/4");
  EXPECT_EQ(s.index, 3);
  EXPECT_EQ(s.count, 4);
  EXPECT_EQ(s.Text(), "3/4");
  EXPECT_TRUE(ParseShard("--shard", "0/1").IsWhole());
}

TEST(ShardTest, RejectsWhatIsNotAShard) {
  for (const char* bad : {"4/4", "-1/4", "1", "1/0", "a/4", "1/4x", "", "/", "1/100001", " 1/4"}) {
    try {
      ParseShard("--shard", bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                "--shard: must be I/N with 0 <= I < N <= 100000 (shard I of N), got '" +
                    std::string(bad) + "'");
    }
  }
}

}  // namespace
}  // namespace foresight
