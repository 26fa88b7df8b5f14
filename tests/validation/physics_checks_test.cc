// foresight check's spec loader, two check kinds that can pass and fail, and the JUnit XML.
#include "validation/physics_checks.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <string>
#include <utility>
#include <variant>

#include "common/error.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

std::filesystem::path Spec(const std::string& name, const std::string& checks) {
  return testing::WriteTempFile("physics_checks_" + std::to_string(::getpid()) + "_" + name,
                                R"({"name": "t", "checks": [)" + checks + "]}");
}

std::string LoadError(const std::filesystem::path& file) {
  try {
    LoadCheckSuite(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

constexpr const char* kRoll =
    R"({"name": "roll", "kind": "free_roll", "field": "spl", "speed_mps": 1.0, "heading_deg": 30, "max_error_rel": MAX, "max_lateral_m": 0.01})";

std::string Roll(const std::string& max_error) {
  std::string text = kRoll;
  text.replace(text.find("MAX"), 3, max_error);
  return text;
}

const CheckSpec& Named(const CheckSuite& suite, const std::string& name) {
  for (const CheckSpec& spec : suite.checks) {
    if (spec.name == name) return spec;
  }
  ADD_FAILURE() << "no check " << name;
  return suite.checks.front();
}

TEST(PhysicsChecksTest, ShippedSpecLoads) {
  const CheckSuite suite = LoadCheckSuite(testing::ModelsDir() / "check_specs" / "default.json");
  EXPECT_EQ(suite.name, "default");
  // Each check is read into its kind's typed settings.
  const CheckSpec& net_spec = Named(suite, "spl_back_net_12mps");
  const auto& net = std::get<NoTunnellingCheck>(net_spec.kind);
  EXPECT_EQ(net.target, ImpactTarget::kBackNet);
  EXPECT_EQ(net.speed_mps, 12.0);
  EXPECT_EQ(net.phases, 20);
  const auto& rebound = std::get<ReboundCheck>(Named(suite, "spl_post_rebound").kind);
  EXPECT_EQ(rebound.speeds_mps, (std::vector<double>{0.3, 1.0, 2.0, 5.0, 10.0}));
  const auto& foot = std::get<RobotReboundCheck>(Named(suite, "nao_foot_rebound").kind);
  EXPECT_EQ(foot.link, "r_foot");
  EXPECT_EQ(foot.speeds_mps, (std::vector<double>{0.5, 1.0, 2.0}));
  EXPECT_EQ(foot.max_error_rel, 0.1);  // issue 29's bound
  EXPECT_EQ(std::get<RobotReboundCheck>(Named(suite, "aibo_paw_rebound").kind).robot, "aibo_ers7");
  const auto& band = std::get<CalibrationBandCheck>(Named(suite, "nao_calibration_band").kind);
  EXPECT_EQ(band.robot, "nao");
  EXPECT_EQ(band.trials, 1000);  // the calibration's own run: a drift guard (issue 12)
  EXPECT_EQ(band.seed, 1u);
  EXPECT_EQ(band.band_rel, 0.05);
}

TEST(PhysicsChecksTest, BadSpecsNameFileAndField) {
  const struct {
    const char* name;
    std::string checks;
    const char* expected;
  } cases[] = {
      {"kind.json", R"({"name": "a", "kind": "levitate"})", "unknown kind 'levitate'"},
      {"key.json",
       R"({"name": "a", "kind": "no_tunnelling", "field": "spl", "target": "post", "speed_mps": 5, "phases": 4, "max_penetration_steps": 1.2, "colour": "red"})",
       "colour"},
      {"target.json",
       R"({"name": "a", "kind": "no_tunnelling", "field": "spl", "target": "goalie", "speed_mps": 5, "phases": 4, "max_penetration_steps": 1.2})",
       "goalie"},
      {"trials.json",
       R"({"name": "a", "kind": "kick_direction", "robot": "nao", "kick": "forward", "kicks": "nao", "trials": 2.5, "max_error_deg": 5})",
       "trials"},
      {"missing.json", R"({"name": "a", "kind": "free_roll", "field": "spl"})", "speed_mps"},
      {"speed.json",
       R"({"name": "a", "kind": "no_tunnelling", "field": "spl", "target": "post", "speed_mps": -5, "phases": 4, "max_penetration_steps": 1.2})",
       "checks[0].speed_mps: must be in [0.05, 20], got -5"},
      {"seed.json",
       R"({"name": "a", "kind": "calibration_band", "robot": "nao", "kicks": "nao", "trials": 20, "seed": 1.5, "band_rel": 0.2, "band_deg": 2})",
       "checks[0].seed: must be a whole number"},
      {"twice.json", Roll("0.02") + "," + Roll("0.02"), "duplicate check name 'roll'"},
      {"empty.json", "", "checks"},
      {"phases.json",
       R"({"name": "a", "kind": "rebound", "field": "spl", "target": "post", "speeds_mps": [1], "phases": 0, "max_error_rel": 0.05, "min_error_mps": 0.005})",
       "checks[0].phases: must be a whole number in [1, 1000], got 0"},
      {"speeds.json",
       R"({"name": "a", "kind": "rebound", "field": "spl", "target": "post", "speeds_mps": [], "phases": 3, "max_error_rel": 0.05, "min_error_mps": 0.005})",
       "checks[0].speeds_mps: must list at least one speed"},
      {"heading.json",
       R"({"name": "a", "kind": "free_roll", "field": "spl", "speed_mps": 1.0, "heading_deg": 1e308, "max_error_rel": 0.02, "max_lateral_m": 0.01})",
       "checks[0].heading_deg: must be in [-360, 360], got 1e+308"},
      {"band.json",
       R"({"name": "a", "kind": "calibration_band", "robot": "nao", "kicks": "nao", "trials": 20, "seed": 1, "band_rel": -1, "band_deg": 2})",
       "checks[0].band_rel"},
  };
  for (const auto& c : cases) {
    const auto file = Spec(c.name, c.checks);
    const std::string message = LoadError(file);
    EXPECT_THAT(message, HasSubstr(file.string())) << c.name;
    EXPECT_THAT(message, HasSubstr(c.expected)) << c.name;
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.name;
  }
}

TEST(PhysicsChecksTest, FreeRollPassesWithinItsToleranceAndFailsWithoutOne) {
  const CheckSuite suite = LoadCheckSuite(Spec("roll.json", Roll("0.02")));
  const std::vector<CheckResult> pass = RunChecks(suite, testing::ModelsDir(), 1, {});
  ASSERT_EQ(pass.size(), 1u);
  EXPECT_TRUE(pass[0].passed) << pass[0].detail;
  EXPECT_THAT(pass[0].detail, HasSubstr("v^2/2a"));
  // No physics engine rolls exactly v^2/2a: a zero tolerance must fail.
  const CheckSuite strict = LoadCheckSuite(Spec("strict.json", Roll("0")));
  EXPECT_FALSE(RunChecks(strict, testing::ModelsDir(), 1, {})[0].passed);
}

TEST(PhysicsChecksTest, FastBallDoesNotTunnelThroughThePost) {
  const CheckSuite suite = LoadCheckSuite(Spec(
      "post.json",
      R"({"name": "post", "kind": "no_tunnelling", "field": "spl", "target": "post", "speed_mps": 10, "phases": 4, "max_penetration_steps": 1.2})"));
  const CheckResult r = RunChecks(suite, testing::ModelsDir(), 1, {})[0];
  EXPECT_TRUE(r.passed) << r.detail;
  EXPECT_THAT(r.detail, HasSubstr("into the post at 4 phases"));
}

TEST(PhysicsChecksTest, ReboundPassesWithTheMaterialsAndFailsWithoutATolerance) {
  const std::string rebound =
      R"({"name": "rebound", "kind": "rebound", "field": "spl", "target": "post", "speeds_mps": [1, 5], "phases": 3, "max_error_rel": TOL, "min_error_mps": MIN})";
  const auto with = [&](const char* tol, const char* min) {
    std::string text = rebound;
    text.replace(text.find("TOL"), 3, tol);
    text.replace(text.find("MIN"), 3, min);
    return text;
  };
  const CheckResult pass =
      RunChecks(LoadCheckSuite(Spec("rebound.json", with("0.05", "0.005"))), testing::ModelsDir(), 1, {})[0];
  EXPECT_TRUE(pass.passed) << pass.detail;
  EXPECT_THAT(pass.detail, HasSubstr("post, e = 0.300"));
  // The solver is not exact to the last bit: no tolerance at all must fail.
  const CheckResult strict =
      RunChecks(LoadCheckSuite(Spec("rebound0.json", with("0", "0"))), testing::ModelsDir(), 1, {})[0];
  EXPECT_FALSE(strict.passed) << strict.detail;
}

TEST(PhysicsChecksTest, RobotReboundPassesWithTheMaterialsAndFailsWithoutATolerance) {
  const std::string rebound =
      R"({"name": "paw", "kind": "robot_rebound", "field": "four_legged", "robot": "aibo_ers7", "link": "rf_lower", "speeds_mps": [1], "max_error_rel": TOL})";
  const auto with = [&](const char* tol) {
    std::string text = rebound;
    text.replace(text.find("TOL"), 3, tol);
    return text;
  };
  const CheckResult pass = RunChecks(LoadCheckSuite(Spec("paw.json", with("0.1"))),
                                     testing::ModelsDir(), 1, {})[0];
  EXPECT_TRUE(pass.passed) << pass.detail;
  EXPECT_THAT(pass.detail, HasSubstr("aibo_ers7 rf_lower, e = 0.180, mu = 0.48"));
  EXPECT_THAT(pass.detail, HasSubstr("hop"));
  const CheckResult strict = RunChecks(LoadCheckSuite(Spec("paw0.json", with("0"))),
                                       testing::ModelsDir(), 1, {})[0];
  EXPECT_FALSE(strict.passed) << strict.detail;
  const std::string bad_link = R"({"name": "paw", "kind": "robot_rebound", "field": "four_legged", "robot": "aibo_ers7", "link": "tail", "speeds_mps": [1], "max_error_rel": 0.1})";
  EXPECT_THROW(RunChecks(LoadCheckSuite(Spec("tail.json", bad_link)), testing::ModelsDir(), 1, {}),
               InputError);
}

// Every check's files and names are read before the first check runs: a spec whose second check
// names a field that does not exist fails at once, naming the file and the check, and runs none.
TEST(PhysicsChecksTest, EveryCheckIsPreparedBeforeAnyRuns) {
  const std::string bad_field =
      R"({"name": "bad_field", "kind": "free_roll", "field": "no_such_field", "speed_mps": 1.0, "heading_deg": 0, "max_error_rel": 0.02, "max_lateral_m": 0.01})";
  const std::string bad_link =
      R"({"name": "bad_link", "kind": "robot_rebound", "field": "spl", "robot": "nao", "link": "tail", "speeds_mps": [1.0], "max_error_rel": 0.1})";
  const std::string bad_kick =
      R"({"name": "bad_kick", "kind": "kick_direction", "robot": "nao", "kick": "bicycle", "kicks": "nao", "trials": 2, "max_error_deg": 5})";
  for (const auto& [name, second] : {std::pair{"field", bad_field}, std::pair{"link", bad_link},
                                     std::pair{"kick", bad_kick}}) {
    const auto file = Spec(std::string("prepared_") + name + ".json", Roll("0.02") + "," + second);
    const CheckSuite suite = LoadCheckSuite(file);
    int ran = 0;
    std::string message = "no error";
    try {
      RunChecks(suite, testing::ModelsDir(), 1, [&](const CheckResult&) { ++ran; });
    } catch (const InputError& e) {
      message = e.what();
    }
    EXPECT_EQ(ran, 0) << name << ": a check ran before the spec was whole";
    EXPECT_THAT(message, HasSubstr(file.string() + ": checks[1] (check 'bad_")) << name;
    EXPECT_EQ(message.find('\n'), std::string::npos) << name;
  }
}

// A kick model or field a check names that does not exist is reported against the check's field.
TEST(PhysicsChecksTest, AMissingFileIsReportedAgainstTheFieldThatNamesIt) {
  const std::string bad_kicks =
      R"({"name": "bad_kicks", "kind": "kick_direction", "robot": "nao", "kick": "forward", "kicks": "no_such_kicks", "trials": 2, "max_error_deg": 5})";
  const auto file = Spec("missing_kicks.json", bad_kicks);
  std::string message = "no error";
  try {
    RunChecks(LoadCheckSuite(file), testing::ModelsDir(), 1, [](const CheckResult&) {});
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_THAT(message, HasSubstr(file.string() + ": checks[0] (check 'bad_kicks'): kicks: refers to "));
  EXPECT_THAT(message, HasSubstr("no_such_kicks.json, which does not exist"));
}

// A file a spec names is found beside the spec, wherever the command runs.
TEST(PhysicsChecksTest, SpecPathsAreRelativeToTheSpecsFolder) {
  const std::filesystem::path dir = testing::FreshTempDir("spec_paths");
  std::ofstream(dir / "my_set.json")
      << R"({"name": "mine", "rotations_deg": [0], "situations": [{"class": "open_field", "file": ")"
      << (testing::ModelsDir() / "situations" / "open_goal.json").string() << R"("}]})";
  std::filesystem::copy_file(testing::ModelsDir() / "kicks" / "nao.json", dir / "my_kicks.json");
  std::ofstream(dir / "spec.json")
      << R"({"checks": [{"name": "floor", "kind": "fidelity_floor", "situations": "my_set.json", "kicks": "my_kicks.json", "trials": 2, "min_tau_b": 0, "max_regret": 1}]})";
  const CheckSuite suite = LoadCheckSuite(dir / "spec.json");
  ASSERT_NE(std::filesystem::current_path(), dir);
  EXPECT_NO_THROW(PrepareCheck(suite.checks.front(), testing::ModelsDir()));
}

TEST(PhysicsChecksTest, JUnitXmlCountsFailuresAndEscapes) {
  std::vector<CheckResult> results(2);
  results[0] = {"a<b", "free_roll", true, "rolled \"far\"", 0.5};
  results[1] = {"c", "kick_direction", false, "off by 9 & more", 1.25};
  const std::string xml = JUnitXml("suite", results);
  EXPECT_THAT(xml, HasSubstr(R"(tests="2" failures="1")"));
  EXPECT_THAT(xml, HasSubstr(R"(name="a&lt;b")"));
  EXPECT_THAT(xml, HasSubstr(R"(<failure message="off by 9 &amp; more"/>)"));
  EXPECT_THAT(xml, HasSubstr(R"(<system-out>rolled &quot;far&quot;</system-out>)"));
  EXPECT_THAT(xml, HasSubstr(R"(time="1.750")"));
  EXPECT_EQ(xml.find("<properties>"), std::string::npos);
  const std::string with = JUnitXml("suite", results, {{"version", "1.2"}, {"spec", "a&b.json"}});
  EXPECT_THAT(with, HasSubstr("<properties>\n      <property name=\"version\" value=\"1.2\"/>\n"
                              "      <property name=\"spec\" value=\"a&amp;b.json\"/>\n"
                              "    </properties>\n    <testcase"));
}

// A spec's names may hold anything: the XML holds their printable form, so it stays well-formed
// (no control character, not even as a reference, is valid XML 1.0) and every byte is UTF-8.
TEST(PhysicsChecksTest, JUnitXmlHoldsNamesInTheirPrintableForm) {
  std::vector<CheckResult> results(1);
  results[0] = {"bell\x01\x1b[31m\u202Eok", "free_roll", false, "line\nbreak \xff", 0.5};
  const std::string xml = JUnitXml("suite\x02", results, {{"spec", "s\x1b.json"}});
  for (const char c : xml) {
    EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20 || c == '\n') << static_cast<int>(c);
  }
  EXPECT_THAT(xml, HasSubstr(R"(name="bell\x01\x1b[31m\u202eok")"));
  EXPECT_THAT(xml, HasSubstr(R"(<failure message="line\nbreak \xff"/>)"));
  EXPECT_THAT(xml, HasSubstr(R"(<testsuite name="suite\x02")"));
  EXPECT_THAT(xml, HasSubstr(R"(value="s\x1b.json")"));
  EXPECT_EQ(xml.find("\xe2\x80\xae"), std::string::npos);
}

}  // namespace
}  // namespace foresight
