// The passing experiment and its ablations in shards (experiments/passing_shard.h,
// experiments/match_trial_shard.h): a trial written to JSON text and read back is the same trial
// bit for bit (trace, events and the team's counters included); shards of both teams' trials and
// of the ablations, merged, give the unsharded results for 1, 2 and 3 shards; a result that is
// not the trial it should be is refused with its place.
#include "experiments/passing_shard.h"

#include <gtest/gtest.h>

#include <bit>
#include <functional>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "experiments/match_trial_shard.h"
#include "experiments/passing_ablations.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

PassingSetup LoadSetup(const std::string& team, int trials, std::vector<int> scenarios) {
  PassingRequest request;
  request.config = "dg";
  request.team = team;
  request.trials = trials;
  request.scenarios = std::move(scenarios);
  return LoadPassingSetup(request, testing::ModelsDir());
}

// What every trial of scenario 1 of `setup` has.
TrialShape ShapeOf(const PassingSetup& setup) {
  const Scenario& s = setup.config.scenarios.front();
  return {static_cast<int>(s.attackers.size()), static_cast<int>(s.opponents.size()),
          setup.config.time_limit_s + setup.sim.control_step_s,
          setup.field.CarpetHalfLength(), setup.field.CarpetHalfWidth()};
}

std::uint64_t Bits(double value) {
  return std::bit_cast<std::uint64_t>(value);
}

void ExpectSamePose(const Vec2& a, const Vec2& b) {
  EXPECT_EQ(Bits(a.x()), Bits(b.x()));
  EXPECT_EQ(Bits(a.y()), Bits(b.y()));
}

void ExpectSameTrial(const MatchTrialResult& a, const MatchTrialResult& b) {
  EXPECT_EQ(a.outcome, b.outcome);
  const TrialCounters &x = a.counters, &y = b.counters;
  EXPECT_EQ(x.opponent_touches, y.opponent_touches);
  EXPECT_EQ(x.opponent_kicks, y.opponent_kicks);
  EXPECT_EQ(x.attacker_backups, y.attacker_backups);
  EXPECT_EQ(x.attacker_kicks, y.attacker_kicks);
  EXPECT_EQ(x.grabs_failed, y.grabs_failed);
  EXPECT_EQ(x.kicks_missed, y.kicks_missed);
  EXPECT_EQ(x.kicks_not_settled, y.kicks_not_settled);
  EXPECT_EQ(x.kicks_fell, y.kicks_fell);
  EXPECT_EQ(x.kicks_blocked, y.kicks_blocked);
  EXPECT_EQ(Bits(x.time_s), Bits(y.time_s));
  ASSERT_EQ(a.attacker_counters.size(), b.attacker_counters.size());
  for (std::size_t i = 0; i < a.attacker_counters.size(); ++i) {
    EXPECT_EQ(a.attacker_counters[i].name, b.attacker_counters[i].name);
    EXPECT_EQ(Bits(a.attacker_counters[i].value), Bits(b.attacker_counters[i].value));
  }
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    const MatchEvent &e = a.events[i], &f = b.events[i];
    EXPECT_EQ(Bits(e.time_s), Bits(f.time_s));
    EXPECT_EQ(e.kind, f.kind);
    EXPECT_EQ(e.side, f.side);
    EXPECT_EQ(e.robot, f.robot);
    ExpectSamePose(e.p_F_ball, f.p_F_ball);
    EXPECT_EQ(e.detail, f.detail);
  }
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (std::size_t i = 0; i < a.trace.size(); ++i) {
    const TraceFrame &p = a.trace[i], &q = b.trace[i];
    EXPECT_EQ(Bits(p.time_s), Bits(q.time_s));
    ExpectSamePose(p.p_F_ball, q.p_F_ball);
    ASSERT_EQ(p.robots.size(), q.robots.size());
    for (std::size_t r = 0; r < p.robots.size(); ++r) {
      ExpectSamePose(p.robots[r].p_F, q.robots[r].p_F);
      EXPECT_EQ(Bits(p.robots[r].theta_rad), Bits(q.robots[r].theta_rad));
    }
  }
}

void ExpectSameResults(const std::vector<PassingResult>& a, const std::vector<PassingResult>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t t = 0; t < a.size(); ++t) {
    ASSERT_EQ(a[t].scenarios.size(), b[t].scenarios.size());
    for (std::size_t s = 0; s < a[t].scenarios.size(); ++s) {
      const ScenarioTrials &x = a[t].scenarios[s], &y = b[t].scenarios[s];
      EXPECT_EQ(x.scenario, y.scenario);
      EXPECT_EQ(x.name, y.name);
      ASSERT_EQ(x.trials.size(), y.trials.size());
      for (std::size_t i = 0; i < x.trials.size(); ++i) {
        SCOPED_TRACE("team " + std::to_string(t) + ", scenario " + x.name + ", trial " +
                     std::to_string(i));
        ExpectSameTrial(x.trials[i], y.trials[i]);
      }
    }
  }
}

// A shard's results as `foresight merge` meets them: written to text and parsed again.
ShardPart PartOf(const Shard& shard, const nlohmann::json& results) {
  ShardPart part;
  part.file = "s" + std::to_string(shard.index) + "/shard.json";
  part.header.shard = shard;
  part.results = nlohmann::json::parse(results.dump());
  return part;
}

TEST(PassingShardTest, ATrialReadBackIsTheSameTrialBitForBit) {
  const PassingSetup setup = LoadSetup("cbr", 2, {1});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  const PassingResult played = RunPassing(setup, "cbr", executor, 5, 1);
  const MatchTrialResult& traced = played.scenarios[0].trials[0];  // the example trial
  ASSERT_FALSE(traced.trace.empty());
  ASSERT_FALSE(traced.events.empty());
  ASSERT_FALSE(traced.attacker_counters.empty());
  for (const MatchTrialResult& trial : played.scenarios[0].trials) {
    const nlohmann::json text = nlohmann::json::parse(TrialShardJson(trial).dump());
    ExpectSameTrial(ReadShardTrial(ShardValue(text, "f", "t"), ShapeOf(setup)), trial);
  }
  // Numbers JSON cannot write (a team's counter may be any double) and odd details.
  MatchTrialResult odd;
  odd.counters.opponent_touches = odd.counters.opponent_kicks = {0, 3};
  odd.counters.attacker_backups = odd.counters.attacker_kicks = {1, 0};
  odd.outcome = TrialOutcome::kPenaltyArea;
  odd.counters.time_s = 1.0 / 3.0;
  odd.counters.kicks_missed = 1;  // each status its own count, read back as written
  odd.counters.kicks_fell = 2;
  odd.counters.kicks_blocked = 3;
  odd.attacker_counters = {{"nan", std::numeric_limits<double>::quiet_NaN()},
                           {"tiny", 5e-324},
                           {"inf", -std::numeric_limits<double>::infinity()}};
  odd.events.push_back({0.1, EventKind::kKick, Side::kOpponents, 1, {-0.0, 2.5}, "a \"b\"\n"});
  odd.trace.push_back({0.2, {1.0, 2.0}, {{{0.1, 0.2}, -3.1}, {}, {}, {{-0.0, 5e-324}, 0.0}}});
  const nlohmann::json text = nlohmann::json::parse(TrialShardJson(odd).dump());
  MatchTrialResult back = ReadShardTrial(ShardValue(text, "f", "t"), {2, 2, 60.0, 4.0, 3.1});
  EXPECT_TRUE(std::isnan(back.attacker_counters[0].value));
  odd.attacker_counters[0].value = back.attacker_counters[0].value = 0.0;
  ExpectSameTrial(back, odd);
}

// What reading `j` as the shard trial at `place` says: its error, or "(no error)".
std::string ShardTrialError(const nlohmann::json& j, const std::string& place) {
  try {
    ReadShardTrial(ShardValue(j, "s/shard.json", place), {2, 2, 60.5, 4.0, 3.1});
  } catch (const InputError& e) {
    return std::string(e.what());
  }
  return std::string("(no error)");
}

// The smallest trial a run could write: one event, two trace frames of the four robots.
MatchTrialResult MinimalTrial() {
  MatchTrialResult trial;
  trial.counters.opponent_touches = trial.counters.opponent_kicks = {0, 0};
  trial.counters.attacker_backups = trial.counters.attacker_kicks = {0, 0};
  trial.events.push_back({});
  trial.trace.push_back({0.0, {0.0, 0.0}, std::vector<Pose2>(4)});
  trial.trace.push_back({0.5, {0.1, 0.0}, std::vector<Pose2>(4)});
  return trial;
}

TEST(PassingShardTest, AMalformedTrialIsRefusedWithItsPlace) {
  const auto error = [](const std::string& text) {
    return ShardTrialError(nlohmann::json::parse(text), "results[4].result");
  };
  const MatchTrialResult trial = MinimalTrial();
  ASSERT_EQ(error(TrialShardJson(trial).dump()), "(no error)");
  nlohmann::json good = TrialShardJson(trial);
  nlohmann::json j = good;
  j["outcome"] = 6;
  EXPECT_EQ(error(j.dump()), "s/shard.json: results[4].result.outcome: must be 0 .. 5");
  j = good;
  j["events"][0][1] = 13;
  EXPECT_EQ(error(j.dump()), "s/shard.json: results[4].result.events[0][1]: must be 0 .. 12");
  j = good;
  j["events"][0].erase(6);
  EXPECT_EQ(error(j.dump()), "s/shard.json: results[4].result.events[0]: must be "
                             "[time_s, kind, side, robot, ball x, ball y, detail]");
  j = good;
  j.erase("counters");
  EXPECT_EQ(error(j.dump()), "s/shard.json: results[4].result.counters: missing");
  j = good;
  j["counters"]["time_s"] = "soon";
  EXPECT_EQ(error(j.dump()),
            "s/shard.json: results[4].result.counters.time_s: must be a number, got \"soon\"");
  // A trace coordinate of 1e308 made `foresight merge` fail on "JSON cannot hold inf" (exit 3).
  j = good;
  j["trace"][1][1] = 1e308;
  EXPECT_EQ(error(j.dump()),
            "s/shard.json: results[4].result.trace[1][1]: must be in [-4, 4], got 1e+308");
  j = good;
  j["events"][0][5] = -3.2;
  EXPECT_EQ(error(j.dump()),
            "s/shard.json: results[4].result.events[0][5]: must be in [-3.1, 3.1], got -3.2");
}

TEST(PassingShardTest, ATrialUnlikeAnyPlayedTrialIsRefusedWithItsPlace) {
  const auto error = [](const nlohmann::json& j) { return ShardTrialError(j, "r"); };
  const nlohmann::json good = TrialShardJson(MinimalTrial());
  ASSERT_EQ(error(good), "(no error)");
  // A later trace frame without robots made `foresight merge` crash; 1 or 3 robots passed.
  for (const int robots : {0, 1, 3, 5}) {
    nlohmann::json j = good;
    j["trace"][1][3] = nlohmann::json::array();
    for (int r = 0; r < robots; ++r) j["trace"][1][3].push_back({0.0, 0.0, 0.0});
    EXPECT_EQ(error(j), "s/shard.json: r.trace[1][3]: must list every robot of the scenario (4), "
                        "got " + std::to_string(robots));
  }
  struct Case {
    std::function<void(nlohmann::json&)> tamper;
    std::string message;
  };
  const std::vector<Case> cases = {
      {[](nlohmann::json& j) { j["counters"]["opponent_kicks"] = {0}; },
       "r.counters.opponent_kicks: must have one count per robot (2), got 1"},
      {[](nlohmann::json& j) { j["counters"]["grabs_failed"] = -1; },
       "r.counters.grabs_failed: must be 0 or more, got -1"},
      {[](nlohmann::json& j) { j["counters"]["time_s"] = 1e308; },
       "r.counters.time_s: must be a time from 0 to the trial's limit 60.5 s"},
      {[](nlohmann::json& j) { j["counters"]["time_s"] = "nan"; },
       "r.counters.time_s: must be a time from 0 to the trial's limit 60.5 s"},
      {[](nlohmann::json& j) { j["counters"]["last_touch"] = {1, 2}; },
       "r.counters.last_touch[1]: must be a robot of its side, 0 .. 1, got 2"},
      {[](nlohmann::json& j) { j["counters"]["last_touch"] = {-1, 0}; },
       "r.counters.last_touch[1]: must be -1 when no robot touched the ball"},
      {[](nlohmann::json& j) { j["counters"]["shots"] = {1, 2}; },
       "r.counters.shots[1]: must not exceed the shots on target"},
      {[](nlohmann::json& j) { j["counters"]["attacker_kick_sent"] = 7; },
       "r.counters.attacker_kick_sent: must be 0 or 1"},
      {[](nlohmann::json& j) { j["events"][0][3] = 2; },
       "r.events[0][3]: must be a robot of its side, 0 .. 1, got 2"},
      {[](nlohmann::json& j) { j["events"][0][4] = "inf"; },
       "r.events[0][4]: must be in [-4, 4], got \"inf\""},
      {[](nlohmann::json& j) { j["trace"][1][0] = -1.0; },
       "r.trace[1][0]: must be a time from 0 to the trial's limit 60.5 s"},
      {[](nlohmann::json& j) { j["trace"][1][3][2][2] = "-inf"; },
       "r.trace[1][3][2][2]: must be a finite number, got \"-inf\""},
  };
  for (const Case& c : cases) {
    nlohmann::json j = good;
    c.tamper(j);
    EXPECT_EQ(error(j), "s/shard.json: " + c.message);
  }
}

TEST(PassingShardTest, BothTeamsMergedFromOneTwoOrThreeShardsEqualTheWholeRun) {
  const PassingSetup setup = LoadSetup("both", 3, {1, 4});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  std::vector<PassingResult> whole;
  for (const std::string& team : setup.teams)
    whole.push_back(RunPassing(setup, team, executor, 9, 2));
  const int items = PassingItems(setup, 2);
  EXPECT_EQ(items, 2 * 2 * 3);
  for (int count : {1, 2, 3}) {
    SCOPED_TRACE(std::to_string(count) + " shards");
    std::vector<ShardPart> parts;
    int played = 0;
    for (int i = 0; i < count; ++i) {
      const Shard shard{i, count};
      std::vector<PassingResult> mine;
      for (std::size_t t = 0; t < setup.teams.size(); ++t) {
        mine.push_back(RunPassing(setup, setup.teams[t], executor, 9, 1, {},
                                  TeamShard(setup, static_cast<int>(t), shard)));
      }
      const nlohmann::json results = PassingShardResults(setup, setup.teams, mine, shard);
      played += static_cast<int>(results.size());
      parts.push_back(PartOf(shard, results));
    }
    EXPECT_EQ(played, items);  // every trial played once
    ExpectSameResults(MergePassingShards(setup, setup.teams, parts), whole);
  }
}

TEST(PassingShardTest, AShardPlaysOnlyItsTrials) {
  const PassingSetup setup = LoadSetup("reactive", 4, {2});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  // Of the 4 trials of a one-team run of one scenario, shard 1/3 owns trial 1 only.
  const PassingResult part = RunPassing(setup, "reactive", executor, 2, 1, {}, Shard{1, 3});
  const auto& trials = part.scenarios[0].trials;
  ASSERT_EQ(trials.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    // A played trial has events (its end at least), one not played has none.
    EXPECT_EQ(trials[i].events.empty(), i != 1) << i;
  }
}

TEST(PassingShardTest, AblationsMergedFromOneTwoOrThreeShardsEqualTheWholeRun) {
  const PassingSetup setup = LoadSetup("both", 2, {3});
  std::vector<PassingVariant> variants = LoadPassingVariants("cbr_variants", testing::ModelsDir());
  variants.resize(3);  // the paper's team and two variants: three CBR teams and the reactive one
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  const std::vector<PassingResult> whole = PlayAblations(setup, variants, executor, 4, 2);
  const std::vector<std::string> teams = AblationTeams(variants);
  ASSERT_EQ(teams.size(), 4u);
  EXPECT_EQ(teams.front(), "reactive");
  for (int count : {1, 2, 3}) {
    SCOPED_TRACE(std::to_string(count) + " shards");
    std::vector<ShardPart> parts;
    for (int i = 0; i < count; ++i) {
      const Shard shard{i, count};
      parts.push_back(PartOf(shard, PassingShardResults(
                                        setup, teams,
                                        PlayAblations(setup, variants, executor, 4, 1, {}, shard),
                                        shard)));
    }
    ExpectSameResults(MergePassingShards(setup, teams, parts), whole);
  }
}

TEST(PassingShardTest, AResultForAnotherTrialIsRefused) {
  const PassingSetup setup = LoadSetup("reactive", 2, {1, 2});
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  const std::vector<std::string> teams = {"reactive"};
  const Shard shard{0, 2};  // items 0 and 2: trial 0 of scenarios 1 and 2
  const nlohmann::json results = PassingShardResults(
      setup, teams, {RunPassing(setup, "reactive", executor, 1, 1, {}, shard)}, shard);
  const auto error = [&](const nlohmann::json& changed) {
    try {
      MergePassingShards(setup, teams, {PartOf(shard, changed)});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  nlohmann::json j = results;
  j[1]["scenario"] = 1;
  EXPECT_EQ(error(j), "s0/shard.json: results[1].scenario: must be 2");
  j = results;
  j[0]["trial"] = 1;
  EXPECT_EQ(error(j), "s0/shard.json: results[0].trial: must be 0");
  j = results;
  j[0]["team"] = "cbr";
  EXPECT_EQ(error(j), "s0/shard.json: results[0].team: must be 'reactive'");
  j = results;
  j.erase(1);
  EXPECT_EQ(error(j), "s0/shard.json: results: has no item 1");
  // The recorded trial's trace with a frame emptied of robots: `foresight merge` crashed on it.
  const nlohmann::json& trace = results[0]["result"]["trace"];
  ASSERT_GE(trace.size(), 2u);
  j = results;
  j[0]["result"]["trace"][1][3] = nlohmann::json::array();
  EXPECT_EQ(error(j), "s0/shard.json: results[0].result.trace[1][3]: must list every robot of the "
                      "scenario (4), got 0");
}

}  // namespace
}  // namespace foresight
