// Shard files (report/shard_file.h): exact numbers, and every way a set of shards can fail to be
// one whole run ends in one line naming the file.
#include "report/shard_file.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fstream>
#include <limits>

#include "common/error.h"

namespace foresight {
namespace {

class ShardFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("shard_file_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Writes shard `index` of `count` of a run of `items` items with results 10 * item.
  std::filesystem::path Write(const std::string& name, int index, int count, int items = 10,
                              const std::string& seed = "1", const std::string& version = "9.9") {
    ShardHeader h{"fidelity", version, {index, count}, {{"--seed", seed}}, items, 1.5};
    nlohmann::json results = nlohmann::json::array();
    for (int k = 0; k < h.shard.OwnedCount(items); ++k) results.push_back(10 * h.shard.Item(k));
    const std::filesystem::path folder = dir_ / name;
    std::filesystem::create_directories(folder);
    std::ofstream(folder / kShardFileName) << ShardFileText(h, results);
    return folder;
  }

  std::string Error(const std::vector<std::filesystem::path>& dirs) {
    try {
      ReadShardParts(dirs, "9.9");
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }

  std::filesystem::path dir_;
};

TEST_F(ShardFileTest, ReadsTheShardsOfOneRunInShardOrder) {
  const auto a = Write("a", 2, 3), b = Write("b", 0, 3), c = Write("c", 1, 3);
  const std::vector<ShardPart> parts = ReadShardParts({a, b, c}, "9.9");
  ASSERT_EQ(parts.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(parts[i].header.shard.index, i);
    EXPECT_EQ(parts[i].header.items, 10);
    EXPECT_EQ(parts[i].header.run_time_s, 1.5);
    EXPECT_EQ(parts[i].results[0], 10 * i);  // the shard's first item is its index
  }
  EXPECT_EQ(parts[0].results.size(), 4u);  // items 0, 3, 6, 9
  EXPECT_EQ(ResultsOf(parts[1]).At(2).Int(), 70);
}

TEST_F(ShardFileTest, NumbersReadBackToTheSameBits) {
  const double values[] = {0.1, -0.0, 1.0 / 3.0, 5e-324, 1.7976931348623157e308, -2.5e-17,
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()};
  nlohmann::json list = nlohmann::json::array();
  for (double v : values) list.push_back(ExactJson(v));
  list.push_back(ExactJson(std::numeric_limits<double>::quiet_NaN()));
  const nlohmann::json back = nlohmann::json::parse(list.dump());
  const ShardValue read(back, "f", "x");
  for (std::size_t i = 0; i < std::size(values); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(read.At(i).Double()),
              std::bit_cast<std::uint64_t>(values[i]))
        << values[i];
  }
  EXPECT_TRUE(std::isnan(read.At(std::size(values)).Double()));
}

TEST_F(ShardFileTest, AMissingShardIsNamed) {
  EXPECT_EQ(Error({Write("a", 0, 4), Write("b", 1, 4), Write("d", 3, 4)}),
            "merge: shard(s) 2 of this 'fidelity' run (0 .. 3) missing; 3 folders given");
}

TEST_F(ShardFileTest, AShardGivenTwiceIsRefused) {
  const auto a = Write("a", 0, 2), b = Write("b", 1, 2), b2 = Write("b2", 1, 2);
  EXPECT_EQ(Error({a, b, b2}),
            (b2 / "shard.json").string() + ": shard 1/2 is given twice (also " +
                (b / "shard.json").string() + ")");
}

TEST_F(ShardFileTest, ShardsOfAnotherRunAreRefused) {
  const auto a = Write("a", 0, 2);
  EXPECT_EQ(Error({a, Write("seed", 1, 2, 10, "2")}),
            (dir_ / "seed/shard.json").string() + ": setting --seed is '2', but " +
                (a / "shard.json").string() + " has '1' (shards of different runs)");
  EXPECT_EQ(Error({a, Write("count", 1, 3)}),
            (dir_ / "count/shard.json").string() + ": the shard count is '3', but " +
                (a / "shard.json").string() + " has '2' (shards of different runs)");
  EXPECT_EQ(Error({a, Write("items", 1, 2, 12)}),
            (dir_ / "items/shard.json").string() + ": the item count is '12', but " +
                (a / "shard.json").string() + " has '10' (shards of different runs)");
  EXPECT_EQ(Error({a, Write("version", 1, 2, 10, "1", "9.8")}),
            (dir_ / "version/shard.json").string() + ": foresight_version is '9.8', but " +
                (a / "shard.json").string() + " has '9.9' (shards of different runs)");
  EXPECT_EQ(Error({Write("old", 0, 1, 10, "1", "0.1")}),
            (dir_ / "old/shard.json").string() +
                ": made by foresight 0.1, this is 9.9 (merge with the version that ran the shards)");
}

TEST_F(ShardFileTest, FoldersThatAreNotShardsAreRefused) {
  EXPECT_EQ(Error({dir_ / "none"}),
            (dir_ / "none").string() + ": no such shard folder (the --out of a run with --shard)");
  std::filesystem::create_directories(dir_ / "empty");
  EXPECT_EQ(Error({dir_ / "empty"}),
            (dir_ / "empty").string() + ": no shard.json (not the --out of a run with --shard)");
  // A shard file cut short, and one whose results do not fit its shard.
  const auto a = Write("a", 0, 1);
  std::filesystem::resize_file(a / kShardFileName, 100);
  EXPECT_NE(Error({a}).find(": invalid JSON at "), std::string::npos) << Error({a});
  const auto b = Write("b", 0, 2, 10);
  std::string text;
  {
    std::ifstream in(b / kShardFileName);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  text.replace(text.find("\"items\": 10"), 11, "\"items\": 12");
  std::ofstream(b / kShardFileName) << text;
  EXPECT_EQ(Error({b}), (b / "shard.json").string() +
                            ": results: 5 items, but shard 0/2 of 12 has 6");
}

// A shard of format 1 (before blocked stances had a status of their own, its missed counts
// hold them) is refused in one line, not merged with a meaning it does not have.
TEST_F(ShardFileTest, AShardOfAnOlderFormatIsRefusedInOneLine) {
  const auto a = Write("a", 0, 1);
  std::string text;
  {
    std::ifstream in(a / kShardFileName);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string current = "\"foresight_shard\": " + std::to_string(kShardFormat);
  ASSERT_NE(text.find(current), std::string::npos) << text;
  text.replace(text.find(current), current.size(), "\"foresight_shard\": 1");
  std::ofstream(a / kShardFileName) << text;
  EXPECT_EQ(Error({a}), (a / "shard.json").string() +
                            ": foresight_shard: format 1 is not this foresight's (2); run the "
                            "shard again with this foresight");
}

TEST_F(ShardFileTest, OutcomesRoundTrip) {
  Outcome o;
  o.p_F_rest = {1.0 / 3.0, -2.75};
  o.category = Category::kOut;
  o.first_contact = Contact::kRobot;
  o.time_s = 0.123456789;
  o.status = OutcomeStatus::kNotSettled;
  const nlohmann::json j = nlohmann::json::parse(OutcomeShardJson(o).dump());
  const Outcome back = ReadShardOutcome(ShardValue(j, "f", "o"));
  EXPECT_EQ(back.p_F_rest, o.p_F_rest);
  EXPECT_EQ(back.category, o.category);
  EXPECT_EQ(back.first_contact, o.first_contact);
  EXPECT_EQ(back.time_s, o.time_s);
  EXPECT_EQ(back.status, o.status);
  for (int s = 0; s < kOutcomeStatusCount; ++s) {  // blocked included
    o.status = static_cast<OutcomeStatus>(s);
    const nlohmann::json text = nlohmann::json::parse(OutcomeShardJson(o).dump());
    EXPECT_EQ(ReadShardOutcome(ShardValue(text, "f", "o")).status, o.status) << s;
  }
  const nlohmann::json bad = nlohmann::json::parse("[0, 0, 7, 0, 0, 0]");
  try {
    ReadShardOutcome(ShardValue(bad, "f", "o"));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "f: o[2]: must be 0 .. 3");
  }
}

}  // namespace
}  // namespace foresight
