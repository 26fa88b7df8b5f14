// One slice of a long run's work, for spreading it over processes or machines.
//
// A run of `items` independent work items (fidelity situations, stability poses, strategy
// starts) split into `count` shards gives item i to shard i mod count: interleaved, so that
// items of different cost (situations near the posts, poses near a goal) spread evenly, and
// deterministic, so that the shards of one run on any machines cover every item exactly once.
// Results never depend on the split: an item draws its random numbers from its own index.
#pragma once

#include <string>

namespace foresight {

struct Shard {
  int index = 0;  // 0 .. count - 1
  int count = 1;

  bool IsWhole() const { return count == 1; }
  bool Owns(int item) const { return item % count == index; }
  // How many of items 0 .. items - 1 this shard owns, and the k-th of them.
  int OwnedCount(int items) const { return items > index ? (items - index - 1) / count + 1 : 0; }
  int Item(int k) const { return index + k * count; }
  // This shard seen from item `first` on, for a run whose items come in blocks (a block of
  // trials per team): the result owns j exactly when this shard owns first + j.
  Shard From(int first) const { return {((index - first) % count + count) % count, count}; }
  std::string Text() const;  // "I/N"
};

// Parses "I/N" (0 <= I < N <= kMaxShards); InputError "FIELD: must be I/N with ..., got 'TEXT'".
inline constexpr int kMaxShards = 100000;  // far above any cluster's job array (assumption)
Shard ParseShard(const std::string& field, const std::string& text);

}  // namespace foresight
