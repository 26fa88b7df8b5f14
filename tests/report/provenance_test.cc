// The provenance every report carries: inputs in order, replaced in place, and its JSON and HTML
// pieces.
#include "report/provenance.h"

#include <gtest/gtest.h>

namespace foresight {
namespace {

RunProvenance Example() {
  RunProvenance p;
  p.version = "1.2.3";
  p.seed = 7;
  p.run_time_s = 12.34;
  p.inputs = {{"file", "experiments/a.json"}, {"situation", "scene"}};
  return p;
}

TEST(ProvenanceTest, SetInputReplacesInPlaceOrAppends) {
  RunProvenance p = Example();
  p.SetInput("file", "experiments/b.json");
  p.SetInput("kicks", "kicks/nao.json");
  ASSERT_EQ(p.inputs.size(), 3u);
  EXPECT_EQ(p.inputs[0].key, "file");
  EXPECT_EQ(p.Input("file"), "experiments/b.json");
  EXPECT_EQ(p.inputs[2].key, "kicks");
  EXPECT_EQ(p.Input("missing"), "");
}

TEST(ProvenanceTest, InputsKeepTheirOrderInTheJson) {
  nlohmann::ordered_json j{{"experiment", "x"}};
  AddInputsJson(j, Example());
  EXPECT_EQ(j.dump(), R"({"experiment":"x","file":"experiments/a.json","situation":"scene"})");
  EXPECT_EQ(InputsJson(RunProvenance{}).dump(), "{}");
}

TEST(ProvenanceTest, HtmlRowsEndWithVersionAndRunTime) {
  const auto rows = ProvenanceRows(Example());
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], (std::pair<std::string, std::string>{"version", "1.2.3"}));
  EXPECT_EQ(rows[1], (std::pair<std::string, std::string>{"run time", "12.3 s"}));
}

}  // namespace
}  // namespace foresight
