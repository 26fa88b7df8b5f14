// The motion search on a tiny budget: the same settings give the same bytes whatever the thread
// count, the first candidate is the shipped motion, the refusal rules refuse, the score adds
// what the objective says, bad settings name their field, and a written motion file loads back
// as the candidate.
#include "tools/motion_search.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/error.h"
#include "common/geometry.h"
#include "tests/support/model_test_util.h"
#include "tests/support/temp_files.h"
#include "tools/motion_search_output.h"

namespace foresight {
namespace {

using testing::ModelsDir;
using testing::WriteTempFile;

// A fixed base keeps a trial at about 10 ms; two rounds of three and two candidates, two trials.
std::string TinySettings(const std::string& base = "fixed", int seed = 3,
                         const std::string& constraints =
                             R"({"min_clearance_m": 0.005, "max_speed_share": 1.0, "max_fall_share": 0.0, "max_duration_s": 3.0})") {
  return R"({
    "notes": "test: a tiny budget",
    "situation": "nao", "kicks": "nao_calibrated", "kick": "forward", "base": ")" + base + R"(",
    "seed": )" + std::to_string(seed) + R"(,
    "rounds": [
      {"candidates": 3, "trials": 2, "keyframe_sigma_deg": 3, "time_sigma_rel": 0.05, "balance_sigma_deg": 1},
      {"candidates": 2, "trials": 3, "keyframe_sigma_deg": 1, "time_sigma_rel": 0.02, "balance_sigma_deg": 0.5}
    ],
    "constraints": )" + constraints + R"(,
    "objective": {"target_speed_mps": 1.1, "target_direction_deg": 0, "speed_sd_max_mps": 0.05,
                  "sd_weight": 1, "min_speed_mps": 0.98, "low_weight": 1, "direction_max_deg": 3,
                  "direction_weight_per_deg": 0.01, "miss_weight": 1, "fall_weight": 10},
    "keep": 2
  })";
}

struct Search {
  MotionSearchSettings settings;
  std::unique_ptr<PhysicsSetup> setup;
  MotionSearchResult result;
};

Search RunSearch(const std::string& text, int threads) {
  Search s;
  s.settings = LoadMotionSearchSettings(WriteTempFile("search.json", text), ModelsDir());
  s.setup = LoadSearchSetup(s.settings, ModelsDir());
  MotionSearchRun run;
  run.settings = &s.settings;
  run.setup = s.setup.get();
  run.threads = threads;
  s.result = RunMotionSearch(run);
  return s;
}

TEST(MotionSearchTest, SameSeedSameBytesWhateverTheThreadsAndTheBaselineIsTheShippedMotion) {
  const Search one = RunSearch(TinySettings(), 1);
  const Search two = RunSearch(TinySettings(), 2);
  const std::string bytes = SearchJson(one.settings, one.result).dump();
  EXPECT_EQ(bytes, SearchJson(two.settings, two.result).dump());
  ASSERT_EQ(one.result.candidates.size(), 5u);
  const KickMotion& shipped = one.setup->robot.motions[*one.setup->robot.FindMotion("forward")];
  const KickMotion& baseline = one.result.candidates[0].motion;
  ASSERT_EQ(baseline.keyframes.size(), shipped.keyframes.size());
  for (std::size_t k = 0; k < shipped.keyframes.size(); ++k) {
    EXPECT_EQ(baseline.keyframes[k].time_s, shipped.keyframes[k].time_s);
    EXPECT_EQ(baseline.keyframes[k].positions_rad, shipped.keyframes[k].positions_rad);
  }
  // The shipped forward kick launches near 1.08 m/s on the fixed base: it is scored.
  const SearchCandidate& first = one.result.candidates[0];
  EXPECT_EQ(first.refusal, Refusal::kNone);
  EXPECT_EQ(first.summary.trials, 2);
  EXPECT_NEAR(first.summary.launch_speed_mean_mps, 1.08, 0.1);
  // Other candidates moved the inner keyframes and kept the stance at both ends.
  const KickMotion& drawn = one.result.candidates[1].motion;
  EXPECT_NE(drawn.keyframes[2].positions_rad, shipped.keyframes[2].positions_rad);
  EXPECT_EQ(drawn.keyframes.front().positions_rad, shipped.keyframes.front().positions_rad);
  EXPECT_EQ(drawn.keyframes.back().positions_rad, shipped.keyframes.back().positions_rad);
  // The best list holds the scored candidates in order of score.
  ASSERT_FALSE(one.result.best.empty());
  for (std::size_t k = 1; k < one.result.best.size(); ++k) {
    EXPECT_LE(one.result.candidates[one.result.best[k - 1]].score,
              one.result.candidates[one.result.best[k]].score);
  }
  // The second round's candidate 0 is the first round's best, scored again on the second
  // round's trials, and the best list ranks the last round's candidates only.
  const int first_best = [&] {
    int best = -1;
    for (int i = 0; i < 3; ++i) {
      const SearchCandidate& c = one.result.candidates[static_cast<std::size_t>(i)];
      if (c.refusal == Refusal::kNone &&
          (best < 0 || c.score < one.result.candidates[static_cast<std::size_t>(best)].score)) {
        best = i;
      }
    }
    return best;
  }();
  ASSERT_GE(first_best, 0);
  const SearchCandidate& incumbent = one.result.candidates[3];
  EXPECT_EQ(incumbent.round, 1);
  EXPECT_EQ(incumbent.index, 0);
  EXPECT_EQ(incumbent.summary.trials, 3);  // its own round's trials, not the first round's 2
  const KickMotion& round_best = one.result.candidates[static_cast<std::size_t>(first_best)].motion;
  for (std::size_t k = 0; k < round_best.keyframes.size(); ++k) {
    EXPECT_EQ(incumbent.motion.keyframes[k].time_s, round_best.keyframes[k].time_s);
    EXPECT_EQ(incumbent.motion.keyframes[k].positions_rad, round_best.keyframes[k].positions_rad);
  }
  for (int index : one.result.best) EXPECT_EQ(one.result.candidates[index].round, 1);
  // Another seed draws other candidates.
  const Search other = RunSearch(TinySettings("fixed", 4), 1);
  EXPECT_NE(bytes, SearchJson(other.settings, other.result).dump());
}

TEST(MotionSearchTest, RefusalRulesRefuseBeforeAnyTrial) {
  const Search slow = RunSearch(
      TinySettings("fixed", 3,
                   R"({"min_clearance_m": 0.005, "max_speed_share": 0.1, "max_fall_share": 0.0, "max_duration_s": 3.0})"),
      1);
  for (const SearchCandidate& c : slow.result.candidates) {
    EXPECT_EQ(c.refusal, Refusal::kSpeed);
    EXPECT_EQ(c.summary.trials, 0);
  }
  EXPECT_TRUE(slow.result.best.empty());
  const Search high = RunSearch(
      TinySettings("fixed", 3,
                   R"({"min_clearance_m": 0.5, "max_speed_share": 1.0, "max_fall_share": 0.0, "max_duration_s": 3.0})"),
      1);
  // The speed rule comes first: a drawn candidate may be refused for speed instead.
  EXPECT_EQ(high.result.candidates[0].refusal, Refusal::kClearance);
  for (const SearchCandidate& c : high.result.candidates) {
    EXPECT_NE(c.refusal, Refusal::kNone);
    EXPECT_EQ(c.summary.trials, 0);
  }
}

TEST(MotionSearchTest, FloatingBaseShiftsTheBalanceAndCountsFalls) {
  std::string text = TinySettings("floating");
  text = testing::ReplaceOnce(text, R"("candidates": 3, "trials": 2)", R"("candidates": 2, "trials": 1)");
  text = testing::ReplaceOnce(text, R"("candidates": 2, "trials": 3)", R"("candidates": 1, "trials": 1)");
  const Search s = RunSearch(text, 1);
  ASSERT_EQ(s.result.candidates.size(), 3u);
  const KickMotion& shipped = s.setup->robot.motions[*s.setup->robot.FindMotion("forward")];
  const SearchCandidate& baseline = s.result.candidates[0];
  EXPECT_EQ(baseline.refusal, Refusal::kNone);
  EXPECT_EQ(baseline.summary.fell, 0);
  // A drawn candidate changes every offset's magnitude by the same amount, keeping the signs.
  const KickMotion& drawn = s.result.candidates[1].motion;
  ASSERT_EQ(drawn.balance.offsets_rad.size(), shipped.balance.offsets_rad.size());
  const double change = std::abs(drawn.balance.offsets_rad[0].second) -
                        std::abs(shipped.balance.offsets_rad[0].second);
  EXPECT_NE(change, 0.0);
  for (std::size_t k = 0; k < shipped.balance.offsets_rad.size(); ++k) {
    EXPECT_NEAR(std::abs(drawn.balance.offsets_rad[k].second) -
                    std::abs(shipped.balance.offsets_rad[k].second),
                change, 1e-12);
    EXPECT_EQ(std::signbit(drawn.balance.offsets_rad[k].second),
              std::signbit(shipped.balance.offsets_rad[k].second));
  }
  // A robot that stands but sways past max_tilt_deg is refused for balance, after its trials.
  EXPECT_GT(baseline.summary.max_tilt_rad, 0.0);
  const Search strict = RunSearch(
      testing::ReplaceOnce(text, R"("max_duration_s": 3.0})", R"("max_duration_s": 3.0, "max_tilt_deg": 0})"), 1);
  const SearchCandidate& swayed = strict.result.candidates[0];
  EXPECT_EQ(swayed.refusal, Refusal::kBalance);
  EXPECT_EQ(swayed.summary.fell, 0);
  EXPECT_EQ(swayed.summary.trials, 1);
}

// A motion too fast for its joints is slowed where it is too fast, its poses kept.
TEST(MotionSearchTest, FitToSpeedLimitSlowsTheSegmentsThatAreTooFast) {
  const Robot robot = LoadRobot("nao", ModelsDir());
  const KickMotion& shipped = robot.motions[*robot.FindMotion("forward_long")];
  const double share = FindPeakJointSpeed(shipped, robot.model).share;
  KickMotion motion = shipped;
  FitToSpeedLimit(motion, robot.model, 0.6 * share);
  EXPECT_LE(FindPeakJointSpeed(motion, robot.model).share, 0.6 * share);
  EXPECT_GT(motion.DurationS(), shipped.DurationS());
  for (std::size_t k = 0; k < motion.keyframes.size(); ++k) {
    EXPECT_EQ(motion.keyframes[k].positions_rad, shipped.keyframes[k].positions_rad);
  }
  EXPECT_EQ(motion.keyframes[1].time_s, shipped.keyframes[1].time_s);  // the lift was slow enough
  KickMotion untouched = shipped;
  FitToSpeedLimit(untouched, robot.model, 1.0);
  EXPECT_EQ(untouched.DurationS(), shipped.DurationS());
}

TEST(MotionSearchTest, ScoreAddsTheObjectivesTerms) {
  SearchObjective o;
  o.target_speed_mps = 1.5;
  o.speed_sd_max_mps = 0.1;
  o.sd_weight = 2.0;
  o.low_weight = 3.0;
  o.direction_max_rad = 3.0 * kDegToRad;
  o.direction_weight = 0.5 * kRadToDeg;  // 0.5 per degree
  o.miss_weight = 4.0;
  o.fall_weight = 10.0;
  TrialSummary s;
  s.trials = 10;
  s.touched = 9;
  s.launched = 8;
  s.fell = 1;
  s.launch_speed_mean_mps = 1.3;
  s.launch_speed_sd_mps = 0.15;
  s.launch_direction_mean_rad = -5.0 * kDegToRad;
  const double expected = 0.2 + 2.0 * 0.05 + 3.0 * 0.25 + 0.5 * 2.0 + 4.0 * 0.2 + 10.0 * 0.1;
  EXPECT_NEAR(ScoreCandidate(o, s, 0.25), expected, 1e-9);
}

TEST(MotionSearchTest, BadSettingsNameTheFileAndField) {
  const auto error_of = [](const std::string& text) {
    try {
      LoadMotionSearchSettings(WriteTempFile("bad_search.json", text), ModelsDir());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of(testing::ReplaceOnce(TinySettings(), R"("candidates": 3, "trials": 2)", R"("candidates": 3, "trials": 0)"))
                .find("rounds[0].trials: must be in [1, 100000], got 0"),
            std::string::npos);
  EXPECT_NE(error_of(testing::ReplaceOnce(TinySettings(), R"("base": "fixed")", R"("base": "flying")"))
                .find("base: must be one of fixed, floating, got 'flying'"),
            std::string::npos);
  EXPECT_NE(error_of(testing::ReplaceOnce(TinySettings(), R"("keep": 2)", R"("keep": 2, "kep": 1)"))
                .find("kep"),
            std::string::npos);
  const std::string message =
      error_of(testing::ReplaceOnce(TinySettings(), R"("max_speed_share": 1.0)", R"("max_speed_share": 1.2)"));
  EXPECT_NE(message.find("bad_search.json"), std::string::npos) << message;
  EXPECT_NE(message.find("constraints.max_speed_share: must be in [0.01, 1], got 1.2"),
            std::string::npos)
      << message;
  EXPECT_NE(error_of(testing::ReplaceOnce(TinySettings(), R"("max_duration_s": 3.0})",
                                          R"("max_duration_s": 3.0, "max_tilt_deg": 91})"))
                .find("constraints.max_tilt_deg: must be in [0, 90], got 91"),
            std::string::npos);
  // An unknown kick is named with the file.
  const MotionSearchSettings settings = LoadMotionSearchSettings(
      WriteTempFile("kick_search.json",
                    testing::ReplaceOnce(TinySettings(), R"("kick": "forward")", R"("kick": "lob")")),
      ModelsDir());
  EXPECT_THROW(LoadSearchSetup(settings, ModelsDir()), InputError);
}

// A start motion replaces the shipped one as the first round's centre, and a file that is not
// the kick's motion is refused with its field.
TEST(MotionSearchTest, AStartMotionIsTheFirstCentre) {
  const std::filesystem::path shipped =
      ModelsDir() / "robots" / "nao" / "motions" / "forward.json";
  std::ifstream in(shipped);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The ball 1 mm nearer: a motion the robot does not ship.
  const KickMotion original = LoadKickMotion(shipped);
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(text);
  j["ball_x_m"] = original.p_R_ball.x() - 0.001;
  const std::filesystem::path moved = WriteTempFile("start_forward.json", j.dump(2));
  const std::string settings = testing::ReplaceOnce(
      TinySettings(), R"("kick": "forward",)", R"("kick": "forward", "start": ")" + moved.string() + R"(",)");
  const Search s = RunSearch(settings, 1);
  EXPECT_EQ(s.settings.start_file, moved);
  EXPECT_EQ(s.result.candidates[0].motion.p_R_ball.x(), original.p_R_ball.x() - 0.001);
  // The files written take the start's layout and notes, with the candidate's figures.
  const KickMotion written = LoadKickMotion(
      WriteTempFile("start_best.json", MotionFileText(moved, s.result.candidates[0].motion)));
  EXPECT_EQ(written.p_R_ball.x(), original.p_R_ball.x() - 0.001);

  const auto setup_error = [](const std::string& text) {
    try {
      LoadSearchSetup(LoadMotionSearchSettings(WriteTempFile("start_search.json", text), ModelsDir()),
                      ModelsDir());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(setup_error(testing::ReplaceOnce(TinySettings(), R"("kick": "forward",)",
                                             R"("kick": "forward", "start": "no_such_motion.json",)"))
                .find("start: no motion file"),
            std::string::npos);
  const std::filesystem::path side = ModelsDir() / "robots" / "nao" / "motions" / "side_kick_left.json";
  EXPECT_NE(setup_error(testing::ReplaceOnce(TinySettings(), R"("kick": "forward",)",
                                             R"("kick": "forward", "start": ")" + side.string() + R"(",)"))
                .find("name: must be 'forward' (the kick of robot 'nao'), got 'side_kick_left'"),
            std::string::npos);
}

// A round's own tilt limit refuses in that round only, after the trials: the candidates are
// drawn and played as without it, so the last round's limit only leaves the swaying ones out
// of the ranking (how the shipped side kicks were picked).
TEST(MotionSearchTest, ARoundsTiltLimitRefusesAfterTheTrialsInThatRoundOnly) {
  const std::string free = TinySettings("floating");
  const std::string limited = testing::ReplaceOnce(
      free, R"("balance_sigma_deg": 0.5})", R"("balance_sigma_deg": 0.5, "max_tilt_deg": 0.001})");
  const Search a = RunSearch(free, 2);
  const Search b = RunSearch(limited, 2);
  ASSERT_EQ(a.result.candidates.size(), b.result.candidates.size());
  int refused = 0;
  for (std::size_t i = 0; i < a.result.candidates.size(); ++i) {
    const SearchCandidate& x = a.result.candidates[i];
    const SearchCandidate& y = b.result.candidates[i];
    EXPECT_EQ(x.summary.launch_speed_mean_mps, y.summary.launch_speed_mean_mps) << i;
    EXPECT_EQ(x.summary.max_tilt_rad, y.summary.max_tilt_rad) << i;
    if (x.round == 0 || x.refusal != Refusal::kNone) {
      EXPECT_EQ(x.refusal, y.refusal) << i;
    } else {
      EXPECT_EQ(y.refusal, Refusal::kBalance) << i;  // every robot tilts a little
      ++refused;
    }
  }
  EXPECT_GT(refused, 0);
  // All of the last round refused: the ranking is the first round's, as the file says.
  for (int index : b.result.best) EXPECT_EQ(b.result.candidates[index].round, 0);
}

// Every shipped settings file (models/motion_search/) loads and sets up its search (the setup
// refuses a kick its robot has no motion for, and checks a start motion as a shipped one).
TEST(MotionSearchTest, EveryShippedSettingsFileLoads) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(ModelsDir() / "motion_search")) {
    if (!entry.is_regular_file()) continue;  // start/ holds the searches' start motions
    const MotionSearchSettings settings = LoadMotionSearchSettings(entry.path(), ModelsDir());
    EXPECT_NO_THROW(LoadSearchSetup(settings, ModelsDir())) << entry.path();
    ++files;
  }
  EXPECT_GE(files, 3);
}

TEST(MotionSearchTest, AWrittenMotionFileLoadsBackAsTheCandidate) {
  const Search s = RunSearch(TinySettings(), 2);
  ASSERT_FALSE(s.result.best.empty());
  const SearchCandidate& best = s.result.candidates[s.result.best[0]];
  const int m = *s.setup->robot.FindMotion("forward");
  const std::string text =
      MotionFileText(s.setup->robot.spec.kick_motion_files[m].second, best.motion);
  const KickMotion loaded = LoadKickMotion(WriteTempFile("best_1.json", text));
  ASSERT_EQ(loaded.keyframes.size(), best.motion.keyframes.size());
  for (std::size_t k = 0; k < loaded.keyframes.size(); ++k) {
    EXPECT_NEAR(loaded.keyframes[k].time_s, best.motion.keyframes[k].time_s, 1e-6);
    for (std::size_t j = 0; j < loaded.joints.size(); ++j) {
      EXPECT_NEAR(loaded.keyframes[k].positions_rad[j], best.motion.keyframes[k].positions_rad[j],
                  1e-4 * kDegToRad);
    }
  }
  EXPECT_EQ(loaded.p_R_ball, best.motion.p_R_ball);
  EXPECT_EQ(loaded.stance.base_height_m, best.motion.stance.base_height_m);
}

// The command: bad input is one line naming the file and field, exit status 2, nothing written;
// a run writes search.json and the best motions.
TEST(MotionSearchCommandTest, BadSettingsExitTwoAndGoodOnesWriteTheirFiles) {
  const std::filesystem::path out = testing::FreshTempDir("search_out");
  const std::filesystem::path bad = WriteTempFile(
      "cmd_bad.json", testing::ReplaceOnce(TinySettings(), R"("seed": 3)", R"("seed": -1)"));
  const std::string command = std::string(FORESIGHT_MOTION_SEARCH) + " " + bad.string() +
                              " --out " + (out / "bad").string() + " --models " +
                              ModelsDir().string() + " 2>" + (out / "err.txt").string();
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream err(out / "err.txt");
  std::string line, rest;
  std::getline(err, line);
  EXPECT_NE(line.find("cmd_bad.json: seed: must be in [0, 2147483647], got -1"), std::string::npos)
      << line;
  EXPECT_FALSE(std::getline(err, rest));  // one line
  EXPECT_FALSE(std::filesystem::exists(out / "bad"));

  const std::filesystem::path good = WriteTempFile("cmd_good.json", TinySettings());
  const std::string run = std::string(FORESIGHT_MOTION_SEARCH) + " " + good.string() + " --out " +
                          (out / "good").string() + " --threads 1 --models " +
                          ModelsDir().string() + " >" + (out / "log.txt").string();
  const int ok = std::system(run.c_str());
  ASSERT_TRUE(WIFEXITED(ok));
  EXPECT_EQ(WEXITSTATUS(ok), 0);
  EXPECT_TRUE(std::filesystem::exists(out / "good" / "search.json"));
  EXPECT_TRUE(std::filesystem::exists(out / "good" / "best_1.json"));
  EXPECT_NO_THROW(LoadKickMotion(out / "good" / "best_1.json"));
}

// The tool's flags as the command's: an empty value and a flag given twice are refused in one
// line before anything is read, not taken for "not given" or the last one given.
TEST(MotionSearchCommandTest, EmptyAndRepeatedFlagsAreRefused) {
  const std::filesystem::path out = testing::FreshTempDir("search_flags");
  const std::filesystem::path good = WriteTempFile("cmd_flags.json", TinySettings());
  const auto error = [&](const std::string& flags) {
    const std::string command = std::string(FORESIGHT_MOTION_SEARCH) + " " + good.string() + " " +
                                flags + " 2>" + (out / "err.txt").string();
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << flags;
    std::ifstream err(out / "err.txt");
    return std::string(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
  };
  const std::string dir = (out / "r").string();
  EXPECT_EQ(error("--out " + dir + " --models ''"),
            "foresight_motion_search: error: --models: empty value (leave the flag out for its "
            "default)\n");
  EXPECT_EQ(error("--out " + dir + " --out " + dir + "2"),
            "foresight_motion_search: error: --out: given twice\n");
  EXPECT_EQ(error("--out " + dir + " --threads 1 --threads 2"),
            "foresight_motion_search: error: --threads: given twice\n");
  EXPECT_FALSE(std::filesystem::exists(out / "r"));
}

// --out is a report folder: checked before the search (nothing is searched for an output that
// cannot be written) and replaced whole after it, so a smaller run leaves no best_<rank>.json of
// a larger one behind, and a user's own file there stays.
TEST(MotionSearchCommandTest, OutIsCheckedFirstAndReplacedWhole) {
  const std::filesystem::path out = testing::FreshTempDir("search_out_whole");
  const auto run = [&](const std::string& settings, const std::filesystem::path& dir) {
    const std::filesystem::path file = WriteTempFile("cmd_whole.json", settings);
    const std::string command = std::string(FORESIGHT_MOTION_SEARCH) + " " + file.string() +
                                " --out " + dir.string() + " --threads 1 --models " +
                                ModelsDir().string() + " >" + (out / "log.txt").string() + " 2>" +
                                (out / "err.txt").string();
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  const auto read = [](const std::filesystem::path& file) {
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  // A parent that cannot be made (a file is in the way): refused before the first round is
  // searched (and printed).
  { std::ofstream(out / "a_file") << "x"; }
  EXPECT_EQ(run(TinySettings(), out / "a_file" / "r"), 2);
  EXPECT_EQ(read(out / "log.txt"), "");
  EXPECT_NE(read(out / "err.txt").find("--out: cannot create the folder"), std::string::npos)
      << read(out / "err.txt");

  const std::filesystem::path dir = out / "search";
  // At least three of the last round's four candidates are scored (the best list ranks that round).
  const std::string keep_three = testing::ReplaceOnce(
      testing::ReplaceOnce(TinySettings(), R"("keep": 2)", R"("keep": 3)"),
      R"({"candidates": 2, "trials": 3)", R"({"candidates": 4, "trials": 3)");
  ASSERT_EQ(run(keep_three, dir), 0) << read(out / "err.txt");
  EXPECT_TRUE(std::filesystem::exists(dir / "best_3.json"));
  { std::ofstream(dir / "notes.txt") << "the user's"; }
  ASSERT_EQ(run(testing::ReplaceOnce(TinySettings(), R"("keep": 2)", R"("keep": 1)"), dir), 0)
      << read(out / "err.txt");
  EXPECT_TRUE(std::filesystem::exists(dir / "best_1.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "best_2.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "best_3.json"));
  EXPECT_EQ(read(dir / "notes.txt"), "the user's");
}

}  // namespace
}  // namespace foresight
