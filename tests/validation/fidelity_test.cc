// The fidelity comparison: snapping to the candidate grid, a tiny physics-backed run (same
// numbers with one thread or two, metrics in range), and loading situation sets.
#include "validation/fidelity.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "common/checks.h"
#include "common/error.h"
#include "common/geometry.h"
#include "planner/coarse_planner.h"
#include "tests/support/test_situations.h"
#include "validation/candidate_grid.h"
#include "validation/fidelity_set.h"
#include "validation/fidelity_shard.h"
#include "validation/fidelity_views.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

// A file in the shared temporary folder, unique per test and process.
std::filesystem::path TempFile(const std::string& name, const std::string& text) {
  return testing::WriteTempFile("fidelity_test_" + std::to_string(::getpid()) + "_" + name, text);
}

std::string ReadText(const std::string& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string Shipped(const std::string& situation) {
  return (testing::ModelsDir() / "situations" / (situation + ".json")).string();
}

std::vector<double> Degrees(std::vector<double> deg) {
  for (double& d : deg) d *= kDegToRad;
  return deg;
}

TEST(CandidateGridTest, SnapsToTheNearestRotationOnTheCircle) {
  const Situation situation = testing::MakeSituation({});
  const CoarsePlanner planner(situation);
  CoarseActionEvaluator inner = planner.MakeEvaluator(20, 1);
  const CandidateGridEvaluator grid(
      inner, Degrees({-150, -120, -90, -60, -30, 0, 30, 60, 90, 120, 150, 180}));
  const auto snap_deg = [&](double deg) { return grid.Snap(deg * kDegToRad) / kDegToRad; };
  EXPECT_NEAR(snap_deg(170), 180, 1e-9);
  EXPECT_NEAR(snap_deg(-175), 180, 1e-9);  // across the back: the list says +180
  EXPECT_NEAR(snap_deg(190), 180, 1e-9);
  EXPECT_NEAR(snap_deg(14), 0, 1e-9);
  EXPECT_NEAR(snap_deg(16), 30, 1e-9);
  EXPECT_NEAR(snap_deg(-164), -150, 1e-9);
  EXPECT_NEAR(snap_deg(-44), -30, 1e-9);
  EXPECT_NEAR(snap_deg(-46), -60, 1e-9);
  EXPECT_NEAR(snap_deg(360), 0, 1e-9);

  const CandidateGridEvaluator minus(inner, Degrees({-180, -90, 0, 90}));
  EXPECT_NEAR(minus.Snap(175 * kDegToRad) / kDegToRad, -180, 1e-9);
  EXPECT_NEAR(minus.Snap(-175 * kDegToRad) / kDegToRad, -180, 1e-9);
  EXPECT_NEAR(minus.Snap(50 * kDegToRad) / kDegToRad, 90, 1e-9);
}

TEST(CandidateGridTest, EvaluatesTheSnappedRotation) {
  const Situation situation = testing::MakeSituation({.x_m = 2.0, .theta_deg = 10.0});
  const CoarsePlanner planner(situation);
  CoarseActionEvaluator inner = planner.MakeEvaluator(50, 3);
  CoarseActionEvaluator reference = planner.MakeEvaluator(50, 3);
  CandidateGridEvaluator grid(inner, Degrees({-90, 0, 90}));
  for (int kick = 0; kick < grid.kick_count(); ++kick) {
    const ActionEvaluation snapped = grid.Evaluate(kick, 50 * kDegToRad);
    const ActionEvaluation direct = reference.Evaluate(kick, 90 * kDegToRad);
    EXPECT_EQ(snapped.utility, direct.utility) << kick;
    EXPECT_EQ(snapped.counts, direct.counts) << kick;
  }
  EXPECT_THROW(CandidateGridEvaluator(inner, {}), std::invalid_argument);
}

// --- a tiny run -------------------------------------------------------------------------------

FidelitySet TinySet(const std::string& tag) {
  const auto file = TempFile(tag + "_set.json",
                             R"({"name": "tiny", "rotations_deg": [-30, 0, 30], "situations": [
      {"class": "near_opp_goal", "file": ")" +
                                 Shipped("open_goal") + R"("},
      {"class": "obstacles", "file": ")" +
                                 Shipped("blocked_by_defender") + R"("}]})");
  return LoadFidelitySet(file.string(), testing::ModelsDir());
}

FidelityResult RunTiny(const FidelitySet& set, int threads) {
  FidelitySettings settings;
  settings.physics_trials = 4;
  settings.converged_samples = 200;
  settings.seed = 7;
  settings.threads = threads;
  // The fixed base, the cheap approximation (a tenth of a floating trial's cost): these tests
  // are of the run's bookkeeping (threads, shards, metrics' ranges), not of the base.
  settings.base = RobotBase::kFixed;
  return RunFidelity(set, testing::ModelsDir(), settings);
}

void ExpectSame(const ActionEvaluation& a, const ActionEvaluation& b, const std::string& what) {
  EXPECT_EQ(a.utility, b.utility) << what;
  EXPECT_EQ(a.trimmed_utility, b.trimmed_utility) << what;
  EXPECT_EQ(a.counts, b.counts) << what;
  EXPECT_EQ(a.too_risky, b.too_risky) << what;
}

TEST(FidelityTest, TinyRunIsTheSameWithOneThreadOrTwo) {
  const FidelitySet set = TinySet("threads");
  const FidelityResult one = RunTiny(set, 1);
  const FidelityResult two = RunTiny(set, 2);
  ASSERT_EQ(one.situations.size(), 2u);
  ASSERT_EQ(two.situations.size(), 2u);
  EXPECT_EQ(one.physics_trials_run, two.physics_trials_run);
  for (std::size_t s = 0; s < 2; ++s) {
    const SituationFidelity& a = one.situations[s];
    const SituationFidelity& b = two.situations[s];
    ASSERT_EQ(a.candidates.size(), b.candidates.size());
    for (std::size_t i = 0; i < a.candidates.size(); ++i) {
      const std::string what = "situation " + std::to_string(s) + " candidate " + std::to_string(i);
      ExpectSame(a.candidates[i].coarse, b.candidates[i].coarse, what + " coarse");
      ExpectSame(a.candidates[i].converged, b.candidates[i].converged, what + " converged");
      ExpectSame(a.candidates[i].physics, b.candidates[i].physics, what + " physics");
      EXPECT_EQ(a.candidates[i].physics_ci.low, b.candidates[i].physics_ci.low) << what;
      EXPECT_EQ(a.candidates[i].physics_ci.high, b.candidates[i].physics_ci.high) << what;
    }
    EXPECT_EQ(a.physics_best, b.physics_best);
    for (auto m : {&SituationFidelity::coarse, &SituationFidelity::converged}) {
      EXPECT_EQ((a.*m).choice, (b.*m).choice);
      EXPECT_EQ((a.*m).tau_b, (b.*m).tau_b);
      EXPECT_EQ((a.*m).top1, (b.*m).top1);
      EXPECT_EQ((a.*m).regret, (b.*m).regret);
    }
    ASSERT_EQ(a.decisions.size(), b.decisions.size());
    for (std::size_t d = 0; d < a.decisions.size(); ++d) {
      EXPECT_EQ(a.decisions[d].coarse_kick, b.decisions[d].coarse_kick);
      EXPECT_EQ(a.decisions[d].physics_kick, b.decisions[d].physics_kick);
      EXPECT_EQ(a.decisions[d].coarse_rotation_rad, b.decisions[d].coarse_rotation_rad);
      EXPECT_EQ(a.decisions[d].physics_rotation_rad, b.decisions[d].physics_rotation_rad);
      EXPECT_EQ(a.decisions[d].agree, b.decisions[d].agree);
      EXPECT_EQ(a.decisions[d].regret, b.decisions[d].regret);
    }
    ASSERT_EQ(a.physics_outcomes.size(), b.physics_outcomes.size());
    for (std::size_t i = 0; i < a.physics_outcomes.size(); ++i) {
      EXPECT_EQ(a.physics_outcomes[i].p_F_rest, b.physics_outcomes[i].p_F_rest);
    }
  }
  ASSERT_EQ(one.classes.size(), two.classes.size());
  for (std::size_t c = 0; c < one.classes.size(); ++c) {
    EXPECT_EQ(one.classes[c].tau_coarse.mean, two.classes[c].tau_coarse.mean);
    EXPECT_EQ(one.classes[c].regret_converged.mean, two.classes[c].regret_converged.mean);
  }
}

TEST(FidelityTest, TinyRunMetricsAreInRange) {
  const FidelitySet set = TinySet("metrics");
  const FidelityResult r = RunTiny(set, 2);
  ASSERT_EQ(r.situations.size(), 2u);
  EXPECT_GT(r.coarse_samples, 0);
  long long trials = 0;
  for (const SituationFidelity& s : r.situations) {
    SCOPED_TRACE(s.file);
    const int kicks = static_cast<int>(s.situation.kicks.kicks.size());
    ASSERT_EQ(s.candidates.size(), static_cast<std::size_t>(3 * kicks));
    for (int k = 0; k < kicks; ++k) {  // each kick at each rotation, once
      for (double deg : {-30.0, 0.0, 30.0}) {
        EXPECT_EQ(std::count_if(s.candidates.begin(), s.candidates.end(),
                                [&](const CandidateScore& c) {
                                  return c.kick_index == k &&
                                         std::abs(c.rotation_rad - deg * kDegToRad) < 1e-12;
                                }),
                  1)
            << k << " " << deg;
      }
    }
    for (const CandidateScore& c : s.candidates) {
      EXPECT_EQ(c.physics.samples, 4);
      EXPECT_EQ(c.converged.samples, 200);
      EXPECT_EQ(c.coarse.samples, r.coarse_samples);
      EXPECT_LE(c.physics_ci.low, c.physics.utility + 1e-12);
      EXPECT_GE(c.physics_ci.high, c.physics.utility - 1e-12);
      EXPECT_LE(c.physics.utility, s.candidates[s.physics_best].physics.utility);
    }
    for (const ChoiceMetrics* m : {&s.coarse, &s.converged}) {
      EXPECT_GE(m->tau_b, -1.0);
      EXPECT_LE(m->tau_b, 1.0);
      EXPECT_GE(m->regret, 0.0);
      ASSERT_GE(m->choice, 0);
      ASSERT_LT(m->choice, static_cast<int>(s.candidates.size()));
      EXPECT_DOUBLE_EQ(m->regret, s.candidates[s.physics_best].physics.utility -
                                      s.candidates[m->choice].physics.utility);
    }
    EXPECT_EQ(s.decisions.size(), 5u);
    for (const StrategyAgreement& d : s.decisions) {
      EXPECT_EQ(d.agree,
                d.coarse_kick == d.physics_kick && d.coarse_rotation_rad == d.physics_rotation_rad);
    }
    EXPECT_GE(s.physics_trials_run, 4LL * 3 * kicks);
    trials += s.physics_trials_run;
  }
  EXPECT_EQ(r.physics_trials_run, trials);
  ASSERT_EQ(r.classes.size(), 3u);
  EXPECT_EQ(r.classes[0].situation_class, "all");
  EXPECT_EQ(r.classes[0].situations, 2);
  EXPECT_EQ(r.classes[0].tau_coarse.n, 2);
  EXPECT_DOUBLE_EQ(r.classes[0].regret_coarse.mean,
                   (r.situations[0].coarse.regret + r.situations[1].coarse.regret) / 2.0);
  EXPECT_EQ(r.classes[1].situation_class, "near_opp_goal");
  EXPECT_EQ(r.classes[1].situations, 1);
  EXPECT_EQ(r.classes[2].situation_class, "obstacles");
  ASSERT_EQ(r.strategies.size(), 5u);
  for (const StrategyAgreementSummary& st : r.strategies) {
    EXPECT_EQ(st.agreement.n, 2);
    EXPECT_GE(st.agreement.mean, 0.0);
    EXPECT_LE(st.agreement.mean, 1.0);
  }
  const std::vector<int> worst = WorstFirst(r);
  ASSERT_EQ(worst.size(), 2u);
  EXPECT_GE(r.situations[worst[0]].coarse.regret, r.situations[worst[1]].coarse.regret);
}

// --- the worst situations' viewers -------------------------------------------------------------

// A situation whose coarse choice kicks, with the given regret and tau.
SituationFidelity Scored(double regret, double tau_b) {
  SituationFidelity s;
  s.candidates.push_back(CandidateScore{});
  s.coarse.regret = regret;
  s.coarse.tau_b = tau_b;
  return s;
}

// The situations run as shard `index` of `count` would run them: each recorded (a view labelled
// with its index in the set) when it may be shown among those run before it, and the views of
// those pushed out dropped; then all put back in set order, as the merge does.
std::vector<SituationFidelity> RunInShards(const std::vector<SituationFidelity>& set, int count) {
  std::vector<SituationFidelity> merged(set.size());
  for (int index = 0; index < count; ++index) {
    std::vector<SituationFidelity> run;
    std::vector<std::size_t> items;
    for (std::size_t i = static_cast<std::size_t>(index); i < set.size(); i += count) {
      SituationFidelity s = set[i];
      if (MayBeShown(run, s)) s.views = {ViewerTrial{std::to_string(i), {}, {}, {}}};
      run.push_back(s);
      items.push_back(i);
      KeepShownViews(run);
    }
    for (std::size_t k = 0; k < items.size(); ++k) merged[items[k]] = run[k];
  }
  return merged;
}

// The worst situations are known only after every situation (and every shard), yet each is
// recorded while it runs: whatever the split into shards, every situation shown has its own
// recording, and at most the shown few per shard keep one (ties in regret and tau, and a NaN tau,
// included: the order is strict).
TEST(FidelityViewsTest, EveryShownSituationKeepsItsRecordingInEveryShardSplit) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<SituationFidelity> set = {
      Scored(0.1, 0.5), Scored(0.5, 0.2),  Scored(0.3, nan), Scored(0.2, 0.9), Scored(0.5, 0.2),
      Scored(0.3, 0.1), Scored(0.0, -1.0), Scored(0.5, nan), Scored(0.3, nan), Scored(0.05, 0.0)};
  std::vector<int> expected = FidelityViewSituations(set);
  EXPECT_EQ(expected, (std::vector<int>{1, 4, 7}));
  for (int count = 1; count <= 5; ++count) {
    SCOPED_TRACE(count);
    const std::vector<SituationFidelity> merged = RunInShards(set, count);
    int recorded = 0;
    for (const SituationFidelity& s : merged) recorded += !s.views.empty();
    EXPECT_LE(recorded, count * kFidelityViewSituations);
    for (int i : expected) {
      ASSERT_EQ(merged[i].views.size(), 1u) << i;
      EXPECT_EQ(merged[i].views[0].label, std::to_string(i));
    }
  }
}

// The tiny run records the shown candidates' first trials (each played again through the
// evaluator that scored it and checked against the scored outcome bit for bit, or the run
// throws), merging its shards gives viewer pages with the unsharded run's bytes, and the pages
// are made from those recordings alone: a shown situation without them is refused, not
// simulated again.
TEST(FidelityViewsTest, PagesComeFromTheRecordedTrialsAndShardsGiveTheSameBytes) {
  const FidelitySet set = TinySet("views");
  FidelitySettings settings;
  settings.physics_trials = 4;
  settings.converged_samples = 200;
  settings.seed = 7;
  settings.threads = 2;
  settings.base = RobotBase::kFixed;  // as above
  const FidelityResult whole = RunFidelity(set, testing::ModelsDir(), settings);
  const std::vector<int> shown = FidelityViewSituations(whole.situations);
  ASSERT_FALSE(shown.empty());
  for (int i : shown) {
    const SituationFidelity& s = whole.situations[i];
    ASSERT_FALSE(s.views.empty()) << s.file;
    for (const ViewerTrial& v : s.views) {
      EXPECT_FALSE(v.trace.frames.empty()) << v.label;
      EXPECT_EQ(v.numbers[0].first, "candidate");
      EXPECT_TRUE(std::any_of(v.numbers.begin(), v.numbers.end(), [](const auto& row) {
        return row.first == "strike";
      })) << v.label;
    }
  }
  std::vector<ShardPart> parts;
  for (int i = 0; i < 2; ++i) {
    FidelitySettings part_settings = settings;
    part_settings.shard = {i, 2};
    const FidelityResult part = RunFidelity(set, testing::ModelsDir(), part_settings);
    ShardPart shard_part;
    shard_part.file = "shard" + part_settings.shard.Text();
    shard_part.header.shard = part_settings.shard;
    shard_part.header.items = static_cast<int>(set.cases.size());
    FidelityResult counted = part;
    // A blocked stance (floating base) cannot happen in this open scene on the fixed base; one
    // per situation of the first shard, on its first candidate, must survive the shard file.
    if (i == 0) {
      for (SituationFidelity& s : counted.situations) {
        ++s.candidates.front().physics_status.blocked;
        ++s.physics_status.blocked;
      }
    }
    shard_part.results = nlohmann::json::parse(FidelityShardResults(counted).dump());
    parts.push_back(shard_part);
  }
  FidelityResult merged = MergeFidelityShards(set, settings, parts);
  const int blocked = static_cast<int>((set.cases.size() + 1) / 2);  // shard 0 of 2: items 0, 2, ..
  EXPECT_EQ(merged.physics_status.blocked, blocked);
  EXPECT_EQ(whole.physics_status.blocked, 0);
  for (std::size_t k = 0; k < merged.situations.size(); ++k) {
    const int expected = k % 2 == 0 ? 1 : 0;
    EXPECT_EQ(merged.situations[k].physics_status.blocked, expected) << k;
    EXPECT_EQ(merged.situations[k].candidates.front().physics_status.blocked, expected) << k;
    EXPECT_EQ(merged.situations[k].physics_status.missed,
              whole.situations[k].physics_status.missed);
  }
  // A value that does not follow from the others is refused with the value found beside the one
  // it must be.
  for (const char* field : {"utility", "trimmed_utility", "p"}) {
    std::vector<ShardPart> tampered = parts;
    nlohmann::json& e = tampered[0].results[0]["candidates"][0]["coarse"];
    nlohmann::json& value = std::string(field) == "p" ? e["p"][0] : e[field];
    value = value.get<double>() + 0.25;
    try {
      MergeFidelityShards(set, settings, tampered);
      ADD_FAILURE() << "a tampered " << field << " was merged";
    } catch (const InputError& error) {
      EXPECT_THAT(error.what(), HasSubstr(", got " + FormatNumber(value.get<double>())))
          << error.what();
    }
  }
  std::vector<ShardPart> flipped = parts;
  nlohmann::json& risky = flipped[0].results[0]["candidates"][0]["coarse"]["too_risky"];
  risky = !risky.get<bool>();
  try {
    MergeFidelityShards(set, settings, flipped);
    ADD_FAILURE() << "a flipped too_risky was merged";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr(risky.get<bool>() ? "false, got true" : "true, got false"))
        << error.what();
  }
  const auto pages = FidelityViewPages(whole, settings, testing::ModelsDir());
  ASSERT_EQ(pages.size(), shown.size());
  EXPECT_EQ(FidelityViewPages(merged, settings, testing::ModelsDir()), pages);
  merged.situations[shown[0]].views.clear();
  try {
    FidelityViewPages(merged, settings, testing::ModelsDir());
    ADD_FAILURE() << "a shown situation without recorded trials made a page";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr(": the fidelity results hold no recorded trials for its viewer"));
  }
}

// --- loading sets -----------------------------------------------------------------------------

void ExpectSetError(const std::string& tag, const std::string& text, const std::string& part) {
  SCOPED_TRACE(tag);
  const auto file = TempFile(tag + ".json", text);
  try {
    LoadFidelitySet(file.string(), testing::ModelsDir());
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string()));
    EXPECT_THAT(e.what(), HasSubstr(part));
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

TEST(FidelitySetTest, BadSetsAreInputErrorsNamingTheFile) {
  const std::string ok_case = R"({"class": "c", "file": ")" + Shipped("open_goal") + R"("})";
  ExpectSetError("empty_rotations", R"({"rotations_deg": [], "situations": [)" + ok_case + "]}",
                 "rotations_deg");
  ExpectSetError("rotation_200", R"({"rotations_deg": [0, 200], "situations": [)" + ok_case + "]}",
                 "rotations_deg");
  ExpectSetError("rotation_minus_181",
                 R"({"rotations_deg": [-181], "situations": [)" + ok_case + "]}", "rotations_deg");
  ExpectSetError("unknown_key",
                 R"({"rotations_deg": [0], "rotation_step": 5, "situations": [)" + ok_case + "]}",
                 "rotation_step");
  ExpectSetError("unknown_case_key",
                 R"({"rotations_deg": [0], "situations": [{"class": "c", "weight": 2, "file": ")" +
                     Shipped("open_goal") + R"("}]})",
                 "weight");
  ExpectSetError(
      "missing_situation",
      R"({"rotations_deg": [0], "situations": [{"class": "c", "file": "no_such_situation.json"}]})",
      "no_such_situation.json");
  ExpectSetError("no_situations", R"({"rotations_deg": [0], "situations": []})", "situations");

  const std::filesystem::path absent =
      std::filesystem::temp_directory_path() / "foresight_tests" /
      ("fidelity_test_" + std::to_string(::getpid()) + "_absent.json");
  try {
    LoadFidelitySet(absent.string(), testing::ModelsDir());
    FAIL() << "a missing set file was read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(absent.string()));
  }
  EXPECT_THROW(LoadFidelitySet("no_such_set", testing::ModelsDir()), InputError);
}

TEST(FidelitySetTest, SituationFilesAreRelativeToTheSet) {
  // A set beside a copy of a situation, naming it relative to itself.
  const auto situation = TempFile("relative_situation.json", ReadText(Shipped("open_goal")));
  const auto file =
      TempFile("relative_set.json",
               R"({"rotations_deg": [180, -90, 45], "situations": [{"class": "c", "file": ")" +
                   situation.filename().string() + R"("}]})");
  const FidelitySet set = LoadFidelitySet(file.string(), testing::ModelsDir());
  EXPECT_EQ(set.name, file.stem().string());  // no name: the file's
  ASSERT_EQ(set.cases.size(), 1u);
  EXPECT_EQ(set.cases[0].file, situation);
  EXPECT_EQ(set.cases[0].shown_file, situation.generic_string());  // outside MODELS: as it is
  EXPECT_EQ(set.cases[0].situation_class, "c");
  ASSERT_EQ(set.rotations_rad.size(), 3u);
  EXPECT_NEAR(set.rotations_rad[0], std::numbers::pi, 1e-12);
  EXPECT_NEAR(set.rotations_rad[2], std::numbers::pi / 4.0, 1e-12);
}

TEST(FidelitySetTest, TheSameTurnListedTwiceIsAnInputError) {
  const auto situation = TempFile("twice_situation.json", ReadText(Shipped("open_goal")));
  const auto file =
      TempFile("twice_set.json",
               R"({"rotations_deg": [180, -180, 45], "situations": [{"class": "c", "file": ")" +
                   situation.filename().string() + R"("}]})");
  try {
    LoadFidelitySet(file.string(), testing::ModelsDir());
    FAIL() << "180 and -180 deg were both accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string()));
    EXPECT_THAT(e.what(), HasSubstr("rotations_deg"));
    EXPECT_THAT(e.what(), HasSubstr("twice"));
  }
}

TEST(FidelitySetTest, ShippedSetsLoad) {
  const FidelitySet quick = LoadFidelitySet("quick", testing::ModelsDir());
  EXPECT_EQ(quick.name, "quick");
  // Reports show shipped situations relative to MODELS: the same bytes in every checkout.
  for (const FidelityCase& c : quick.cases) {
    EXPECT_TRUE(std::filesystem::path(c.shown_file).is_relative()) << c.shown_file;
    EXPECT_TRUE(std::filesystem::equivalent(testing::ModelsDir() / c.shown_file, c.file))
        << c.shown_file;
  }
  EXPECT_EQ(quick.cases[0].shown_file, "fidelity/situations/open_centre.json");
  EXPECT_EQ(quick.cases.size(), 6u);
  EXPECT_EQ(quick.rotations_rad.size(), 12u);
  const FidelitySet def = LoadFidelitySet("default", testing::ModelsDir());
  EXPECT_EQ(def.name, "default");
  EXPECT_EQ(def.cases.size(), 24u);
  EXPECT_EQ(def.rotations_rad.size(), 24u);
  for (const FidelityCase& c : def.cases) {
    EXPECT_FALSE(c.situation_class.empty()) << c.file;
    EXPECT_TRUE(std::filesystem::is_regular_file(c.file)) << c.file;
  }
  // By file name too.
  const FidelitySet by_file = LoadFidelitySet(
      (testing::ModelsDir() / "fidelity" / "quick.json").string(), testing::ModelsDir());
  EXPECT_EQ(by_file.cases.size(), 6u);
}

TEST(FidelitySetTest, AClassKeepsItsSituationsAndTheOverridesApply) {
  SituationOverrides overrides;
  overrides.coarse_rebounds = true;
  const FidelitySet posts =
      LoadFidelitySet("default", testing::ModelsDir(), overrides, "near_posts");
  ASSERT_EQ(posts.cases.size(), 4u);
  for (const FidelityCase& c : posts.cases) {
    EXPECT_EQ(c.situation_class, "near_posts");
    EXPECT_TRUE(c.situation.evaluation.rebounds.enabled);
    EXPECT_EQ(c.situation.evaluation.rebounds.post, 0.3);  // models/physics/spl.json
  }
  try {
    LoadFidelitySet("default", testing::ModelsDir(), {}, "near_post");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--class: no situation of class 'near_post' in "));
    EXPECT_THAT(e.what(), HasSubstr("'open_field', 'near_opp_goal'"));
  }
}

}  // namespace
}  // namespace foresight
