// Bad input to `foresight decide`: each case must end in exactly one line "foresight: error: ..."
// on stderr that names the problem, exit code 2, nothing on stdout, and no file written (not
// even a temporary one) although every case asks for an SVG (docs/ARCHITECTURE.md, "Errors",
// "Output").
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "tests/app/run_foresight.h"

namespace {

namespace fs = std::filesystem;
using foresight::testing::ReplaceOnce;
using foresight::testing::RunResult;
using foresight::testing::ShippedSituation;
using foresight::testing::ShippedText;
using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::StartsWith;

struct BadInput {
  std::string name;
  // Arguments after `decide`; "open_goal" stands for the shipped situation's path.
  std::vector<std::string> args;
  // Files to create in the working folder first: name, then content.
  std::vector<std::pair<std::string, std::string>> files;
  std::vector<std::string> message_parts;  // each must occur in the error line
  std::string known_bug;                   // non-empty: skip and say why
};

void PrintTo(const BadInput& input, std::ostream* os) {
  *os << input.name;
}

std::string OpenGoalWith(const std::string& from, const std::string& to) {
  return ReplaceOnce(ShippedText("open_goal"), from, to);
}

std::vector<BadInput> BadInputs() {
  const std::string open_goal = ShippedSituation("open_goal").string();
  return {
      {"MissingSituationFile",
       {"--situation", "no_such_situation.json"},
       {},
       {"no_such_situation.json", "cannot open file"},
       ""},
      {"JsonSyntaxError",
       {"--situation", "broken.json"},
       {{"broken.json", OpenGoalWith("\"kicks\": \"nao\",", "\"kicks\": nao,")}},
       {"broken.json", "invalid JSON at line 5, column"},
       ""},
      {"UnknownStrategy",
       {"--situation", open_goal, "--strategy", "best_guess"},
       {},
       {"--strategy", "best_guess", "optimal_one"},
       ""},
      {"ZeroSamples",
       {"--situation", open_goal, "--samples", "0"},
       {},
       {"--samples", "got '0'"},
       ""},
      {"NegativeSamples",
       {"--situation", open_goal, "--samples", "-3"},
       {},
       {"--samples", "must be an integer in [1, 100000]", "got '-3'"},
       ""},
      {"NonNumericSeed", {"--situation", open_goal, "--seed", "abc"}, {}, {"--seed", "abc"}, ""},
      {"NegativeSeed", {"--situation", open_goal, "--seed=-1"}, {}, {"--seed", "got '-1'"}, ""},
      {"MinusOneSamples",
       {"--situation", open_goal, "--samples=-1"},
       {},
       {"--samples", "got '-1'"},
       ""},
      {"HeadingOutOfRange",
       {"--situation", "spin.json"},
       {{"spin.json", OpenGoalWith("\"theta_deg\": 0.0", "\"theta_deg\": 1e20")}},
       {"spin.json", "robot.theta_deg", "got 1e+20"},
       ""},
      {"UnknownFieldInSituation",
       {"--situation", "typo.json"},
       {{"typo.json", OpenGoalWith("\"theta_deg\"", "\"theta_dg\"")}},
       {"typo.json", "robot.theta_dg", "unknown field"},
       ""},
      {"NegativeSigma",
       {"--situation", "negative.json"},
       {{"negative.json", OpenGoalWith("\"sigma_theta_deg\": 5.0", "\"sigma_theta_deg\": -5.0")}},
       {"negative.json", "robot.sigma_theta_deg", "got -5"},
       ""},
      {"InfiniteNumber",
       {"--situation", "infinite.json"},
       {{"infinite.json", OpenGoalWith("\"x_m\": 2.5", "\"x_m\": 1e999")}},
       {"infinite.json", "1e999", "x_m"},
       ""},
      {"MissingKicksFile",
       {"--situation", open_goal, "--kicks", "missing_kicks.json"},
       {},
       {"missing_kicks.json", "does not exist"},
       ""},
      {"SvgIntoMissingDirectory",
       {"--situation", open_goal, "--svg", "no_dir/decision.svg"},
       {},
       {"no_dir/decision.svg", "does not exist"},
       ""},
      // Reliability (issue 16): the reader's limits, and one line whatever the input.
      {"DeeplyNestedValue",
       {"--situation", "deep.json"},
       {{"deep.json",
         OpenGoalWith("\"name\": \"open_goal\"",
                      "\"name\": " + std::string(100000, '[') + std::string(100000, ']'))}},
       {"deep.json", "nested deeper than 64 levels"},
       ""},
      {"DuplicateKey",
       {"--situation", "twice.json"},
       {{"twice.json",
         OpenGoalWith("\"field\": \"spl\",", "\"field\": \"spl\", \"field\": \"x\",")}},
       {"twice.json", "the key \"field\" appears twice"},
       ""},
      {"NulBytes",
       {"--situation", "nul.json"},
       {{"nul.json", ShippedText("open_goal") + std::string(2, '\0')}},
       {"nul.json", "NUL byte"},
       ""},
      {"NewlineInAName",
       {"--situation", "newline.json"},
       {{"newline.json", OpenGoalWith("\"field\": \"spl\"", "\"field\": \"sp\\nl\"")}},
       {"newline.json", "sp\\nl"},
       ""},
      {"HugeStringInAWrongType",
       {"--situation", "huge.json"},
       {{"huge.json",
         OpenGoalWith("\"x_m\": 2.5", "\"x_m\": \"" + std::string(100000, 'a') + "\"")}},
       {"huge.json", "must be a number, got \"aaaa", "(100000 bytes)"},
       ""},
      {"DeviceAsSituation",
       {"--situation", "/dev/zero"},
       {},
       {"/dev/zero", "is not a regular file"},
       ""},
      {"SvgOntoADirectory",
       {"--situation", open_goal, "--svg", "existing_dir"},
       {{"existing_dir/keep.txt", "x"}},
       {"existing_dir"},
       ""},
  };
}

class DecideErrorTest : public foresight::testing::ForesightRun,
                        public ::testing::WithParamInterface<BadInput> {};

TEST_P(DecideErrorTest, OneErrorLineExitTwoNoOutput) {
  const BadInput& input = GetParam();
  if (!input.known_bug.empty()) GTEST_SKIP() << "known bug: " << input.known_bug;
  for (const auto& [name, text] : input.files) {
    fs::create_directories((work() / name).parent_path());
    Write(name, text);
  }
  std::vector<std::string> args = input.args;
  if (std::find(args.begin(), args.end(), "--svg") == args.end()) {
    args.insert(args.end(), {"--svg", "decision.svg"});
  }
  const std::set<std::string> before = Listing();

  const RunResult r = Decide(args);

  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_THAT(r.err, StartsWith("foresight: error: "));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_THAT(r.err, EndsWith("\n"));
  for (const std::string& part : input.message_parts) EXPECT_THAT(r.err, HasSubstr(part));
  EXPECT_EQ(Listing(), before) << "a file was left behind";
}

INSTANTIATE_TEST_SUITE_P(BadInput, DecideErrorTest, ::testing::ValuesIn(BadInputs()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
