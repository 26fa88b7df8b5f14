// The partial result of one shard of a long run (DIR/shard.json) and the checks that
// make `foresight merge` exact.
//
// A run given `--shard I/N` computes only its items (common/shard.h) and writes, instead of its
// report, one JSON file: what ran (command, foresight version, the settings that decide the
// results, the shard and the run's item count) and its items' results, numbers written so that
// they read back to the same bits. `foresight merge` reads the shards of one run, refuses any
// set that is not exactly shards 0 .. N-1 of one run (same command, version, settings, N and
// items), puts the items back in item order and writes the report an unsharded run writes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "common/shard.h"
#include "models/outcome.h"

namespace foresight {

inline constexpr std::string_view kShardFileName = "shard.json";
// The format of a shard file's results. 2: physics trials whose stance was blocked are counted
// as `blocked`, no longer among the missed (status lists have four counts, outcome status codes
// reach 4); a format-1 shard is refused, since its missed counts hold the blocked trials.
inline constexpr int kShardFormat = 2;
// A shard file holds one slice of a run's raw results: a 10,000-start strategies run is about
// 10 MB whole, so 1 GiB is far above any real shard (assumption) and below this machine's memory.
inline constexpr std::uintmax_t kMaxShardBytes = std::uintmax_t{1} << 30;

struct ShardHeader {
  std::string command;  // "fidelity", "experiment stability", ...
  std::string version;  // foresight's
  Shard shard;
  // Everything that decides the results: the flags as given (not --out, --threads, --shard).
  nlohmann::ordered_json settings = nlohmann::ordered_json::object();
  int items = 0;  // of the whole run
  double run_time_s = 0.0;
};

// DIR/shard.json's text; `results` holds the shard's items in item order.
std::string ShardFileText(const ShardHeader& header, const nlohmann::json& results);

struct ShardPart {
  std::filesystem::path file;
  ShardHeader header;
  nlohmann::json results;  // an array: the k-th owned item's result at k
};

// Reads DIR/shard.json of every folder and checks that they are the shards 0 .. N-1 of one run
// of `version`, each once. Returns them in shard order. InputError with one line otherwise.
std::vector<ShardPart> ReadShardParts(const std::vector<std::filesystem::path>& dirs,
                                      const std::string& version);

// A shard's run time may be at most this (about 30 years), so that the merge's sum of run times
// stays finite.
inline constexpr double kMaxShardRunTime_s = 1e9;

// Doubles in a shard file: a JSON number reads back to the same bits (nlohmann writes the
// shortest round-trip form); NaN and the infinities, which JSON lacks, are the strings "nan",
// "inf" and "-inf".
nlohmann::json ExactJson(double value);

// A value of a shard file with its place ("FILE: results[3].coarse.utility") for messages.
class ShardValue {
 public:
  ShardValue(const nlohmann::json& value, std::string file, std::string path);
  ShardValue operator[](std::string_view key) const;  // InputError if absent
  ShardValue At(std::size_t index) const;              // of an array
  std::size_t Size() const;                            // of an array
  double Double() const;                               // written by ExactJson
  long long Integer() const;
  int Int() const;
  bool Bool() const;
  std::string String() const;
  bool IsNull() const { return value_->is_null(); }
  bool IsString() const { return value_->is_string(); }
  // Checked against the range the producer guarantees, so that a tampered or damaged shard is
  // refused with its place ("FILE: results[3].p[0]: must be in [0, 1], got -5") instead of
  // reaching a report or a model:
  double Finite() const;                       // a finite number
  double InRange(double lo, double hi) const;  // a number in [lo, hi]; NaN never
  int Count() const;                           // an integer >= 0
  int IntInRange(int lo, int hi) const;        // an integer in [lo, hi]
  [[noreturn]] void Fail(const std::string& problem) const;

 private:
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
};

// The results of `part` as a ShardValue array.
ShardValue ResultsOf(const ShardPart& part);

// An outcome of the seam (models/outcome.h) in a shard file: [x, y, category, first contact,
// time, status], the enums by their numbers.
nlohmann::json OutcomeShardJson(const Outcome& outcome);
Outcome ReadShardOutcome(const ShardValue& value);
nlohmann::json OutcomesShardJson(const std::vector<Outcome>& outcomes);
std::vector<Outcome> ReadShardOutcomes(const ShardValue& value);

}  // namespace foresight
