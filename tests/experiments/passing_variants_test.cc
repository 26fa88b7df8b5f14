// The CBR team's variants: each shipped variant changes what its name says and nothing else;
// bad variant files are refused with the file, the field and the value.
#include "experiments/passing_variants.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

PassingSetup Base() {
  PassingRequest request;
  request.config = "dg";
  request.team = "cbr";
  request.trials = 1;
  return LoadPassingSetup(request, testing::ModelsDir());
}

const PassingVariant& Named(const std::vector<PassingVariant>& variants, const std::string& name) {
  for (const PassingVariant& v : variants) {
    if (v.name == name) return v;
  }
  throw std::runtime_error("no variant " + name);
}

TEST(PassingVariantsTest, ShippedVariantsChangeWhatTheyName) {
  const PassingSetup base = Base();
  const auto variants = LoadPassingVariants("cbr_variants", testing::ModelsDir());
  ASSERT_EQ(variants.front().name, "paper");
  const PassingSetup paper = variants.front().Apply(base);
  EXPECT_EQ(paper.retrieval.cost, base.retrieval.cost);
  EXPECT_EQ(paper.cbr.retrievers, base.cbr.retrievers);
  EXPECT_EQ(Named(variants, "max_cost").Apply(base).retrieval.cost, CostFunction::kMax);
  EXPECT_EQ(Named(variants, "independent").Apply(base).cbr.positioning, Positioning::kIndependent);
  EXPECT_FALSE(Named(variants, "no_free_path").Apply(base).retrieval.free_path);
  EXPECT_FALSE(Named(variants, "no_opponent_similarity").Apply(base).retrieval.opponent_similarity);
  EXPECT_EQ(Named(variants, "order_cost_first").Apply(base).retrieval.order[0],
            RankCriterion::kBandThenCost);
  EXPECT_EQ(Named(variants, "one_retriever").Apply(base).cbr.retrievers, 1);
  // Without the y mirrors each goal keeps one copy of every hand-written case, none mirrored in y.
  const CaseBase& all = base.case_base.cases;
  const CaseBase lone = Named(variants, "no_mirror_y").Apply(base).case_base.cases;
  EXPECT_EQ(lone.size(), all.size() / 2);
  for (DefendingGoal goal : {DefendingGoal::kCyan, DefendingGoal::kYellow}) {
    EXPECT_EQ(lone.Defending(goal).size(), all.HandWrittenCount());
    for (const Case& c : lone.Defending(goal)) {
      EXPECT_TRUE(c.transform == CaseTransform::kOriginal || c.transform == CaseTransform::kMirrorX)
          << c.name;
    }
  }
  EXPECT_EQ(Named(variants, "loss_30").Apply(base).sim.message_loss_rate, 0.3);
  const PassingSetup noisy = Named(variants, "perception_noise").Apply(base);
  EXPECT_EQ(noisy.sim.ball_noise_sigma_m, 0.05);
  EXPECT_EQ(noisy.sim.robot_noise_sigma_m, 0.05);
  EXPECT_EQ(noisy.retrieval.cost, base.retrieval.cost);  // and nothing else
  EXPECT_TRUE(Named(variants, "timing_check").Apply(base).cbr.pass_timing.enabled);
  EXPECT_FALSE(base.cbr.pass_timing.enabled);
}

void ExpectRefused(const std::string& json, const std::string& message) {
  const auto file = testing::WriteTempFile("variants.json", json);
  try {
    LoadPassingVariants(file.string(), testing::ModelsDir());
    ADD_FAILURE() << "accepted: " << json;
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(file.string() + ": " + message));
  }
}

TEST(PassingVariantsTest, BadFilesAreRefusedWithFieldAndValue) {
  ExpectRefused(R"({"variants": [{"name": "a"}, {"name": "a"}]})",
                "variants[1].name: must be a unique, non-empty name, got \"a\"");
  ExpectRefused(R"({"variants": [{"name": "a", "retrieval": {"cost": "median"}}]})",
                "variants[0].retrieval.cost: must be one of");
  ExpectRefused(R"({"variants": [{"name": "a", "retrieval": {"order": ["teammates", "teammates", "conditions"]}}]})",
                "variants[0].retrieval.order: must list");
  ExpectRefused(R"({"variants": [{"name": "a", "team": {"retrievers": 7}}]})",
                "variants[0].team.retrievers: must be 1-4, got 7");
  ExpectRefused(R"({"variants": [{"name": "a", "team": {"speed": 7}}]})", "variants[0].team");
  ExpectRefused(R"({"variants": [{"name": "a", "cases": {"mirror_x": false}}]})",
                "variants[0].cases");
  ExpectRefused(R"({"variants": []})", "variants: must list at least one variant");
}

}  // namespace
}  // namespace foresight
