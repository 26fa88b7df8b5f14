#include "experiments/passing_shard.h"

#include "experiments/match_trial_shard.h"

namespace foresight {

namespace {

// Where item `item` is: its team, scenario (index into the result) and trial.
struct TrialPlace {
  std::size_t team = 0;
  std::size_t scenario = 0;
  std::size_t trial = 0;
};

TrialPlace PlaceOf(const PassingSetup& setup, int item) {
  const int per_team = PassingItems(setup, 1);
  const int in_team = item % per_team;
  return {static_cast<std::size_t>(item / per_team),
          static_cast<std::size_t>(in_team / setup.trials),
          static_cast<std::size_t>(in_team % setup.trials)};
}

// What every trial of the scenario numbered `scenario` (1-based) has.
// A bound for a damaged file, not a figure of the world: a ball leaves the field by at most one
// control step's roll before the referee ends the trial, far less than a metre past the carpet.
constexpr double kBeyondCarpetM = 1.0;

TrialShape ShapeOf(const PassingSetup& setup, int scenario) {
  const Scenario& s = setup.config.scenarios.at(static_cast<std::size_t>(scenario - 1));
  return {static_cast<int>(s.attackers.size()), static_cast<int>(s.opponents.size()),
          setup.config.time_limit_s + setup.sim.control_step_s,
          setup.field.CarpetHalfLength() + kBeyondCarpetM,
          setup.field.CarpetHalfWidth() + kBeyondCarpetM};
}

}  // namespace

int PassingItems(const PassingSetup& setup, int teams) {
  return teams * static_cast<int>(setup.scenarios.size()) * setup.trials;
}

Shard TeamShard(const PassingSetup& setup, int team, const Shard& shard) {
  return shard.From(team * PassingItems(setup, 1));
}

nlohmann::json PassingShardResults(const PassingSetup& setup, const std::vector<std::string>& teams,
                                   const std::vector<PassingResult>& results, const Shard& shard) {
  nlohmann::json items = nlohmann::json::array();
  const int total = PassingItems(setup, static_cast<int>(teams.size()));
  for (int k = 0; k < shard.OwnedCount(total); ++k) {
    const TrialPlace at = PlaceOf(setup, shard.Item(k));
    const ScenarioTrials& st = results[at.team].scenarios[at.scenario];
    items.push_back({{"team", teams[at.team]},
                     {"scenario", st.scenario},
                     {"trial", at.trial},
                     {"result", TrialShardJson(st.trials[at.trial])}});
  }
  return items;
}

std::vector<PassingResult> MergePassingShards(const PassingSetup& setup,
                                              const std::vector<std::string>& teams,
                                              const std::vector<ShardPart>& parts) {
  std::vector<PassingResult> results(teams.size(), EmptyPassingResult(setup));
  const int total = PassingItems(setup, static_cast<int>(teams.size()));
  for (const ShardPart& part : parts) {
    const Shard& shard = part.header.shard;
    const ShardValue items = ResultsOf(part);
    for (int k = 0; k < shard.OwnedCount(total); ++k) {
      const ShardValue item = items.At(k);
      const TrialPlace at = PlaceOf(setup, shard.Item(k));
      ScenarioTrials& st = results[at.team].scenarios[at.scenario];
      if (item["team"].String() != teams[at.team])
        item["team"].Fail("must be '" + teams[at.team] + "'");
      if (item["scenario"].Int() != st.scenario)
        item["scenario"].Fail("must be " + std::to_string(st.scenario));
      if (item["trial"].Int() != static_cast<int>(at.trial))
        item["trial"].Fail("must be " + std::to_string(at.trial));
      st.trials[at.trial] = ReadShardTrial(item["result"], ShapeOf(setup, st.scenario));
    }
  }
  return results;
}

}  // namespace foresight
