// Runs the real `foresight decide` binary on good input and checks what a user gets: the
// decision as text and JSON, determinism under --seed, and the SVG drawing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "tests/app/run_foresight.h"

namespace {

using foresight::testing::CountOf;
using foresight::testing::ReadFile;
using foresight::testing::RunResult;
using foresight::testing::ShippedSituation;
using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;
using DecideCommandTest = foresight::testing::ForesightRun;

// ----- determinism -----

TEST_F(DecideCommandTest, SameSeedGivesByteIdenticalJson) {
  const std::vector<std::string> args = {"--situation", ShippedSituation("open_goal").string(),
                                         "--seed", "7", "--json"};
  const RunResult first = Decide(args);
  const RunResult second = Decide(args);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_FALSE(first.out.empty());
  EXPECT_EQ(first.out, second.out);
}

TEST_F(DecideCommandTest, DifferentSeedDrawsDifferentSamples) {
  const std::string situation = ShippedSituation("open_goal").string();
  const nlohmann::json a = DecideJson({"--situation", situation, "--seed", "1"});
  const nlohmann::json b = DecideJson({"--situation", situation, "--seed", "2"});
  EXPECT_EQ(a["seed"], 1);
  EXPECT_EQ(b["seed"], 2);
  // The situation has state and kick noise, so the hypotheses themselves differ.
  EXPECT_NE(a["kicks"].dump(), b["kicks"].dump());
}

// ----- JSON contract -----

TEST_F(DecideCommandTest, JsonCarriesDecisionStrategyAndPerKickProbabilities) {
  const nlohmann::json j = DecideJson({"--situation", ShippedSituation("open_goal").string()});
  EXPECT_EQ(j["command"], "decide");
  EXPECT_EQ(j["strategy"], "optimal_all");  // the default
  EXPECT_EQ(j["samples"], 30);              // the evaluation file's N
  EXPECT_EQ(j["seed"], 1);
  EXPECT_EQ(j["situation"]["name"], "open_goal");
  EXPECT_THAT(j["situation"]["field"].get<std::string>(), HasSubstr("fields/spl.json"));
  EXPECT_EQ(j["decision"]["kick"], "forward");  // open goal: the forward kick scores
  ASSERT_EQ(j["kicks"].size(), 3u);
  EXPECT_EQ(j["kicks"][0]["name"], "forward");
  EXPECT_EQ(j["kicks"][1]["name"], "side_kick_left");
  EXPECT_EQ(j["kicks"][2]["name"], "side_kick_right");
  EXPECT_GT(j["kicks"][0]["p_opp_goal"].get<double>(), 0.5);
  int chosen = 0;
  for (const nlohmann::json& k : j["kicks"]) {
    SCOPED_TRACE(k["name"].get<std::string>());
    const double total = k["p_opp_goal"].get<double>() + k["p_own_goal"].get<double>() +
                         k["p_out"].get<double>() + k["p_infield"].get<double>();
    EXPECT_NEAR(total, 1.0, 1e-12);
    EXPECT_TRUE(k["considered"].get<bool>());
    EXPECT_LE(k["trimmed_utility"].get<double>(), k["utility"].get<double>());
    if (k["chosen"].get<bool>()) {
      ++chosen;
      EXPECT_EQ(k["name"], j["decision"]["kick"]);
    }
  }
  EXPECT_EQ(chosen, 1);
  EXPECT_TRUE(j["none"].contains("trimmed_utility"));
}

TEST_F(DecideCommandTest, SamplesFlagSetsNAndProbabilitiesAreCountsOverN) {
  const nlohmann::json j =
      DecideJson({"--situation", ShippedSituation("open_goal").string(), "--samples", "8"});
  EXPECT_EQ(j["samples"], 8);
  for (const nlohmann::json& k : j["kicks"]) {
    for (const char* key : {"p_opp_goal", "p_own_goal", "p_out", "p_infield"}) {
      const double count = k[key].get<double>() * 8.0;
      EXPECT_NEAR(count, std::round(count), 1e-9) << k["name"] << " " << key;
    }
  }
}

TEST_F(DecideCommandTest, OptimalOneConsidersOnlyTheForwardKick) {
  const nlohmann::json j = DecideJson(
      {"--situation", ShippedSituation("open_goal").string(), "--strategy", "optimal_one"});
  EXPECT_EQ(j["strategy"], "optimal_one");
  EXPECT_EQ(j["decision"]["kick"], "forward");
  ASSERT_EQ(j["kicks"].size(), 3u);
  for (const nlohmann::json& k : j["kicks"]) {
    EXPECT_EQ(k["considered"].get<bool>(), k["name"] == "forward") << k["name"];
  }
}

TEST_F(DecideCommandTest, KicksFlagReplacesTheKickModel) {
  Write("one_kick.json", R"({"robot": "test", "rolling_deceleration_mps2": 0.27,
      "kicks": [{"name": "poke", "speed_mps": 0.5, "sigma_speed_mps": 0.05,
                 "direction_deg": 0.0, "sigma_direction_deg": 3.0}]})");
  const nlohmann::json j = DecideJson(
      {"--situation", ShippedSituation("open_goal").string(), "--kicks", "one_kick.json"});
  ASSERT_EQ(j["kicks"].size(), 1u);
  EXPECT_EQ(j["kicks"][0]["name"], "poke");
  EXPECT_THAT(j["situation"]["kicks"].get<std::string>(), HasSubstr("one_kick.json"));
}

TEST_F(DecideCommandTest, TextOutputNamesTheDecision) {
  const RunResult r = Decide({"--situation", ShippedSituation("open_goal").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_THAT(r.out, HasSubstr("decision: forward"));
  EXPECT_THAT(r.out, HasSubstr("strategy: optimal_all, 30 samples per hypothesis, seed 1"));
}

// A situation's name is the user's: an ESC, a right-to-left override or a newline in it is
// printed in its printable form, never sent to the terminal.
TEST_F(DecideCommandTest, TextOutputPrintsNamesInTheirPrintableForm) {
  const auto file = Write("odd_name.json", R"({"name": "a\u001b[2Jb\u202ec\nd", "field": "spl",
    "kicks": "nao", "robot": {"x_m": 3.6, "y_m": 1.9, "theta_deg": 10.0, "sigma_x_m": 0.1,
    "sigma_y_m": 0.1, "sigma_theta_deg": 5.0},
    "ball": {"x_m": 0.15, "y_m": 0.0, "sigma_x_m": 0.05, "sigma_y_m": 0.05}})");
  const RunResult r = Decide({"--situation", file.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, StartsWith("situation: a\\x1b[2Jb\\u202ec\\nd ("));
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos);
  EXPECT_EQ(r.out.find("\u202e"), std::string::npos);
}

// ----- SVG -----

TEST_F(DecideCommandTest, SvgIsWellFormedWithOneCirclePerSamplePerKick) {
  const RunResult r = Decide({"--situation", ShippedSituation("open_goal").string(), "--samples",
                              "9", "--svg", "decision.svg"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(Listing(), std::set<std::string>{"decision.svg"});  // no temporary file left
  const std::string svg = ReadFile(work() / "decision.svg");
  EXPECT_THAT(svg, StartsWith("<?xml"));
  EXPECT_THAT(svg, EndsWith("</svg>\n"));
  EXPECT_EQ(CountOf(svg, "<svg "), 1);
  EXPECT_EQ(CountOf(svg, "<g "), CountOf(svg, "</g>"));
  EXPECT_GE(CountOf(svg, "<circle "), 3 * 9);
  // One group per considered kick, holding exactly one circle per sample.
  ASSERT_EQ(CountOf(svg, "<g class=\"kick\">"), 3);
  for (std::size_t at = svg.find("<g class=\"kick\">"); at != std::string::npos;
       at = svg.find("<g class=\"kick\">", at + 1)) {
    const std::string group = svg.substr(at, svg.find("</g>", at) - at);
    EXPECT_EQ(CountOf(group, "<circle "), 9) << group.substr(0, 80);
  }
  // The text decision still goes to stdout.
  EXPECT_THAT(r.out, HasSubstr("decision: forward"));
}

// The colour after every "fill:#" in `text` ("#rgb" or "#rrggbb").
std::vector<std::array<int, 3>> Fills(const std::string& text) {
  std::vector<std::array<int, 3>> fills;
  for (std::size_t at = text.find("fill:#"); at != std::string::npos;
       at = text.find("fill:#", at + 1)) {
    const std::size_t start = at + 6;
    const std::size_t end = text.find_first_not_of("0123456789abcdefABCDEF", start);
    const std::string hex = text.substr(start, end - start);
    const auto part = [&](int i, int digits) {
      const int v = std::stoi(hex.substr(i * digits, digits), nullptr, 16);
      return digits == 1 ? 17 * v : v;
    };
    if (hex.size() == 6) fills.push_back({part(0, 2), part(1, 2), part(2, 2)});
    if (hex.size() == 3) fills.push_back({part(0, 1), part(1, 1), part(2, 1)});
  }
  return fills;
}

double ColourDistance(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

TEST_F(DecideCommandTest, SvgKickColoursDifferFromPostsBallAndEachOther) {
  // side_kick_left's samples were drawn in the yellow of the opponent's posts.
  const RunResult r = Decide({"--situation", ShippedSituation("open_goal").string(), "--samples",
                              "5", "--svg", "colours.svg"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = ReadFile(work() / "colours.svg");
  std::vector<std::array<int, 3>> kicks;  // the first fill of each kick's group
  std::string rest = svg;                  // everything outside the kick groups
  for (std::size_t at; (at = rest.find("<g class=\"kick\">")) != std::string::npos;) {
    const std::size_t end = rest.find("</g>", at);
    const std::string group = rest.substr(at, end - at);
    ASSERT_FALSE(Fills(group).empty());
    kicks.push_back(Fills(group).front());
    rest.erase(at, end - at);
  }
  ASSERT_EQ(kicks.size(), 3u);
  // The field's circles (posts, ball, robots) and the carpet, lines and nets.
  const std::string field = rest.substr(0, rest.find("<text"));
  for (const auto& k : kicks) {
    for (const auto& other : Fills(field)) {
      EXPECT_GT(ColourDistance(k, other), 60.0)
          << k[0] << "," << k[1] << "," << k[2] << " vs " << other[0] << "," << other[1] << ","
          << other[2];
    }
  }
  for (std::size_t i = 0; i < kicks.size(); ++i) {
    for (std::size_t j = i + 1; j < kicks.size(); ++j) {
      EXPECT_GT(ColourDistance(kicks[i], kicks[j]), 60.0) << i << " vs " << j;
    }
  }
}

TEST_F(DecideCommandTest, SvgOfOptimalOneDrawsOnlyTheForwardKick) {
  const RunResult r = Decide({"--situation", ShippedSituation("open_goal").string(), "--strategy",
                              "optimal_one", "--samples", "5", "--svg", "one.svg"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = ReadFile(work() / "one.svg");
  EXPECT_EQ(CountOf(svg, "<g class=\"kick\">"), 1);
  EXPECT_THAT(svg, HasSubstr("<title>forward</title>"));
  EXPECT_THAT(svg, Not(HasSubstr("<title>side_kick_left</title>")));
}

TEST_F(DecideCommandTest, SvgIsTheSameForTheSameSeed) {
  const std::string situation = ShippedSituation("blocked_by_defender").string();
  ASSERT_EQ(Decide({"--situation", situation, "--seed", "3", "--svg", "a.svg"}).exit_code, 0);
  ASSERT_EQ(Decide({"--situation", situation, "--seed", "3", "--svg", "b.svg"}).exit_code, 0);
  EXPECT_EQ(ReadFile(work() / "a.svg"), ReadFile(work() / "b.svg"));
}

}  // namespace
