// `foresight fidelity` against the real binary: a one-situation set writes the JSON, the two CSV
// files and the HTML page; a bad flag is one line, exit code 2, and no folder.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/app/run_foresight.h"

namespace {

namespace fs = std::filesystem;
using foresight::testing::CountOf;
using foresight::testing::ReadFile;
using foresight::testing::RunResult;
using foresight::testing::ShippedSituation;
using ::testing::HasSubstr;
using ::testing::StartsWith;

class FidelityCommandTest : public foresight::testing::ForesightRun {
 protected:
  // A set with one situation (the shipped open goal), each kick at 0 and 90 deg.
  fs::path OneSituationSet() const {
    return Write("set.json", R"({"name": "one", "rotations_deg": [0, 90], "situations": [
        {"class": "near_opp_goal", "file": ")" +
                                 ShippedSituation("open_goal").string() + R"("}]})");
  }
  RunResult Fidelity(std::vector<std::string> args) const {
    args.insert(args.begin(), "fidelity");
    return Run(args);
  }
};

TEST_F(FidelityCommandTest, OneSituationWritesJsonCsvAndHtml) {
  const fs::path set = OneSituationSet();
  const RunResult r = Fidelity(
      {"--situations", set.string(), "--trials", "3", "--converged", "100", "--out", "report"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("report/fidelity.html"));
  const fs::path dir = work() / "report";
  const nlohmann::json j = nlohmann::json::parse(ReadFile(dir / "fidelity.json"));
  ASSERT_TRUE(j.contains("classes"));
  ASSERT_TRUE(j.contains("strategies"));
  ASSERT_TRUE(j.contains("situations"));
  EXPECT_EQ(j["situations"].size(), 1u);
  EXPECT_EQ(j["strategies"].size(), 5u);
  ASSERT_GE(j["classes"].size(), 1u);
  EXPECT_EQ(j["classes"][0]["class"], "all");
  EXPECT_EQ(j["classes"][0]["situations"], 1);
  EXPECT_EQ(j["physics_trials"], 3);
  EXPECT_EQ(j["converged_samples"], 100);
  // Three NAO kicks at two rotations, three trials each; the decisions reuse them.
  EXPECT_EQ(j["physics_trials_run"], 18);
  // What the run used: robot, field, the kick model with its content hash, the physics file.
  EXPECT_EQ(j["robot"], "nao");
  EXPECT_EQ(j["field"], "spl");
  EXPECT_EQ(j["kick_model"], "kicks/nao.json");
  EXPECT_THAT(j["kick_model_hash"].get<std::string>(), StartsWith("fnv1a64:"));
  EXPECT_EQ(j["physics_file"], "physics/spl.json");
  // No --base: the record names the base the physics file gave, not a placeholder.
  EXPECT_EQ(j["robot_base"], "floating");
  // Every status is counted, blocked stances included, in all and per situation and candidate.
  for (const char* status :
       {"physics_missed", "physics_not_settled", "physics_fell", "physics_blocked"}) {
    EXPECT_TRUE(j.contains(status)) << status;
    EXPECT_TRUE(j["situations"][0].contains(status)) << status;
    EXPECT_TRUE(j["situations"][0]["candidates"][0].contains(status)) << status;
  }
  EXPECT_FALSE(j["version"].get<std::string>().empty());
  const std::string candidates = ReadFile(dir / "fidelity_candidates.csv");
  EXPECT_EQ(CountOf(candidates, "\n"), 1 + 3 * 2) << candidates;
  const std::string situations = ReadFile(dir / "fidelity_situations.csv");
  EXPECT_EQ(CountOf(situations, "\n"), 2) << situations;
  const std::string html = ReadFile(dir / "fidelity.html");
  EXPECT_THAT(html, HasSubstr("<svg"));
  EXPECT_THAT(html, ::testing::Not(HasSubstr("<script")));
  EXPECT_EQ(CountOf(html, "</html>"), 1);
  EXPECT_THAT(html, HasSubstr("kicks/nao.json (" + j["kick_model_hash"].get<std::string>() + ")"));
  EXPECT_THAT(html, HasSubstr("physics/spl.json"));
  EXPECT_THAT(html, HasSubstr("<th scope=\"row\">robot base</th><td>floating</td>"));
  EXPECT_THAT(html, ::testing::Not(HasSubstr("&lt;field&gt;")));
  // The worst (here: the only) situation links its 3D viewer: the coarse choice's and physics's
  // best candidate's first trials (one candidate when they agree), with their recorded scenes.
  EXPECT_THAT(html, HasSubstr("<a href=\"worst_1_view.html\">"));
  EXPECT_FALSE(fs::exists(dir / "worst_2_view.html"));
  const std::string view = ReadFile(dir / "worst_1_view.html");
  const int shown = CountOf(view, "\"label\":\"coarse choice: ") +
                    CountOf(view, "\"label\":\"physics best: ");
  EXPECT_TRUE(shown == 3 || shown == 6) << shown;
  EXPECT_THAT(view, HasSubstr("\"links_pose\":[["));
}

TEST_F(FidelityCommandTest, KicksFlagIsTheKickModelTheReportNames) {
  const fs::path set = OneSituationSet();
  const fs::path kicks = fs::path(FORESIGHT_TEST_MODELS_DIR) / "kicks" / "nao_calibrated.json";
  const RunResult r = Fidelity({"--situations", set.string(), "--trials", "2", "--converged",
                                "50", "--kicks", kicks.string(), "--out", "report"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(ReadFile(work() / "report" / "fidelity.json"));
  EXPECT_EQ(j["kick_model"], "kicks/nao_calibrated.json");
}

TEST_F(FidelityCommandTest, OneTrialIsOneLineExitTwoAndNoFolder) {
  const fs::path set = OneSituationSet();
  const RunResult r = Fidelity({"--situations", set.string(), "--trials", "1", "--out", "report"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_THAT(r.err, StartsWith("foresight: error: "));
  EXPECT_THAT(r.err, HasSubstr("--trials"));
  EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
  EXPECT_FALSE(fs::exists(work() / "report"));
}

TEST_F(FidelityCommandTest, BadSetIsOneLineExitTwoAndNoFolder) {
  Write("bad_set.json", R"({"rotations_deg": [0, 200], "situations": []})");
  const RunResult r =
      Fidelity({"--situations", "bad_set.json", "--trials", "3", "--out", "report"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, StartsWith("foresight: error: "));
  EXPECT_THAT(r.err, HasSubstr("bad_set.json"));
  EXPECT_EQ(CountOf(r.err, "\n"), 1) << r.err;
  EXPECT_FALSE(fs::exists(work() / "report"));
}

}  // namespace
