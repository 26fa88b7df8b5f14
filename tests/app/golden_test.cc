// A pinned decision: the JSON of one run must not change by a bit unless the model does, on any
// machine (the planner's maths is the project's own, tests/common/fast_math_test.cc). When a
// change to the model is intended, regenerate the file with the command in its "regenerate"
// key and say so in the commit.
#include <nlohmann/json.hpp>

#include "tests/app/run_foresight.h"

namespace {

using foresight::testing::ReadFile;
using foresight::testing::RunResult;
using foresight::testing::ShippedSituation;
using GoldenTest = foresight::testing::ForesightRun;

TEST_F(GoldenTest, NearGoalCornerOptimalAllSeed5) {
  const RunResult run = Decide({"--situation", ShippedSituation("near_goal_corner").string(),
                                "--strategy", "optimal_all", "--seed", "5", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  nlohmann::ordered_json actual = nlohmann::ordered_json::parse(run.out);
  actual["situation"].erase("file");  // the path differs between checkouts
  nlohmann::ordered_json golden =
      nlohmann::ordered_json::parse(ReadFile(std::filesystem::path(FORESIGHT_TEST_SOURCE_DIR) /
                                             "app/golden/near_goal_corner_optimal_all_seed5.json"));
  golden.erase("regenerate");
  EXPECT_EQ(actual.dump(2), golden.dump(2));
}

}  // namespace
