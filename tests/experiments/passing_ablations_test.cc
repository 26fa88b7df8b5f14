// The ablations (experiments/passing_ablations.h): PlayAblations keeps only what the report
// reads, so its report equals the one made from the trials played whole, team by team.
#include "experiments/passing_ablations.h"

#include <gtest/gtest.h>

#include "tests/support/temp_files.h"

namespace foresight {
namespace {

TEST(PassingAblationsTest, TheReportReadsNothingThatPlayAblationsDrops) {
  PassingRequest request;
  request.config = "dg";
  request.team = "both";
  request.trials = 4;
  request.scenarios = {2, 4};
  const PassingSetup setup = LoadPassingSetup(request, testing::ModelsDir());
  std::vector<PassingVariant> variants = LoadPassingVariants("cbr_variants", testing::ModelsDir());
  variants.resize(3);
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  const std::vector<PassingResult> played = PlayAblations(setup, variants, executor, 6, 2);
  std::vector<PassingResult> whole = {RunPassing(setup, "reactive", executor, 6, 2)};
  for (const PassingVariant& v : variants) {
    whole.push_back(RunPassing(v.Apply(setup), "cbr", executor, 6, 2));
  }
  ASSERT_EQ(played.size(), whole.size());
  for (const PassingResult& r : played) {
    for (const ScenarioTrials& st : r.scenarios) {
      for (const MatchTrialResult& t : st.trials) {
        EXPECT_TRUE(t.events.empty());
        EXPECT_TRUE(t.trace.empty());
        EXPECT_GT(t.counters.time_s, 0.0);  // played
      }
    }
  }
  ASSERT_FALSE(whole[1].scenarios[0].trials[0].events.empty());
  const AblationRun a = SummariseAblations(setup, variants, played);
  const AblationRun b = SummariseAblations(setup, variants, whole);
  EXPECT_EQ(AblationsJson(a).dump(), AblationsJson(b).dump());
  EXPECT_EQ(AblationsCsv(a), AblationsCsv(b));
  EXPECT_EQ(AblationsText(a), AblationsText(b));
  EXPECT_EQ(AblationsSvg(a), AblationsSvg(b));
}

}  // namespace
}  // namespace foresight
