#include "experiments/passing.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "cbr/cbr_team.h"
#include "common/checks.h"
#include "common/error.h"
#include "common/parallel_for.h"
#include "common/random.h"
#include "experiments/match_trial_shard.h"
#include "match/opponent_team.h"
#include "models/model_paths.h"
#include "models/physics_params.h"

namespace foresight {

namespace {
const char* const kTeams = "reactive, cbr, both";

void LoadCbrTeam(PassingSetup& s, const std::filesystem::path& models_dir) {
  s.cbr = LoadCbrTeamParams("team", models_dir);
  s.case_base = LoadCaseBase(DefaultCaseBasePath(models_dir), models_dir);
  if (s.case_base.rules.field.name != s.field.name) {
    throw InputError(DefaultCaseBasePath(models_dir).string() + ": field: the cases are for '" +
                     s.case_base.rules.field.name + "', the match plays on '" + s.field.name +
                     "'");
  }
  s.retrieval = LoadRetrievalParams(ResolveModelFile("retrieval", DataFolder::kCbr, ".", models_dir),
                                    s.case_base.rules.field);
  RequireCaseKicks(s.case_base.cases, s.kicks, s.kicks_file);
  // The team's kick trajectories end where the match's kicks end.
  UseKickModelReach(s.kicks, &s.retrieval);
  // The timing check judges the match's robots: their walk and their reach.
  s.cbr.pass_timing.opponent_speed_mps = s.robot.walk_speed_mps;
  s.cbr.pass_timing.receiver_speed_mps = s.robot.walk_speed_mps;
  s.cbr.pass_timing.reach_m = s.robot.body_radius_m + s.field.ball.radius_m;
  // The ball race judges them too; arrivals within one control step are a tie.
  s.cbr.race.speed_mps = s.robot.walk_speed_mps;
  s.cbr.race.reach_m = s.cbr.pass_timing.reach_m;
  s.cbr.race.tie_s = s.sim.control_step_s;
  s.cbr.hold = HoldParamsFor(s.robot, s.sim);
}
}  // namespace

HoldParams HoldParamsFor(const RobotParams& robot, const SimulationParams& sim) {
  HoldParams h;
  h.grab_s = robot.grab_time_s;
  h.dribble_speed_mps = robot.dribble_speed_mps;
  h.dribble_turn_radps = robot.dribble_turn_speed_radps;
  // The teams start the kick kick_launch_s before the limit, so the ball leaves by then.
  h.hold_limit_s = sim.ball_holding_limit_s - robot.kick_launch_s;
  h.launch_s = robot.kick_launch_s;
  return h;
}

HoldParams DefaultHoldParams(const std::filesystem::path& models_dir) {
  const SimulationParams sim =
      LoadSimulationParams(LoadPassingParams("passing", models_dir).simulation, models_dir);
  return HoldParamsFor(LoadRobotParams(sim.robot, models_dir), sim);
}

std::vector<FieldBox> DefaultOpponentRegions(const std::string& config,
                                             const std::filesystem::path& models_dir) {
  const SimulationParams sim =
      LoadSimulationParams(LoadPassingParams("passing", models_dir).simulation, models_dir);
  const FieldSpec field =
      LoadFieldSpec(ResolveModelFile(sim.field, DataFolder::kFields, ".", models_dir));
  const MatchConfig c =
      LoadMatchConfig(config, models_dir, field, sim, LoadRobotParams(sim.robot, models_dir));
  std::vector<FieldBox> regions;
  for (const auto& opponent : c.opponents) regions.push_back(opponent.region);
  return regions;
}

void PassingParams::Validate() const {
  RequireInRange("confidence", confidence, 0.5, 0.999);
  RequireInRange("example_trial", example_trial, 0, 1000000);
  RequireInRange("trace_period_s", trace_period_s, 0.01, 10.0);
  RequireInRange("step_mark_period_s", step_mark_period_s, 0.1, 60.0);
  RequireInRange("kick_moved_min_m", kick_moved_min_m, 0.0, 10.0);
}

PassingParams LoadPassingParams(const std::string& reference,
                                const std::filesystem::path& models_dir) {
  PassingParams p;
  p.file = ResolveModelFile(reference, DataFolder::kExperiments, ".", models_dir);
  const JsonDocument doc = JsonDocument::Load(p.file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys(
      {"simulation", "confidence", "example_trial", "trace_period_s", "step_mark_period_s",
       "kick_moved_min_m", "paper_tables"});
  p.simulation = root.String("simulation");
  p.confidence = root.Number("confidence");
  p.example_trial = root.Integer("example_trial");
  p.trace_period_s = root.Number("trace_period_s");
  p.step_mark_period_s = root.Number("step_mark_period_s");
  p.kick_moved_min_m = root.Number("kick_moved_min_m");
  p.paper_tables = root.String("paper_tables");
  WithFile(p.file.string(), [&] { p.Validate(); });
  return p;
}

std::string PassingTeamNames() {
  return kTeams;
}

PassingSetup LoadPassingSetup(const PassingRequest& request,
                              const std::filesystem::path& models_dir) {
  PassingSetup s;
  if (request.team == "both") {
    s.teams = {"cbr", "reactive"};
  } else if (request.team == "reactive" || request.team == "cbr") {
    s.teams = {request.team};
  } else {
    throw InputError("--team: unknown team '" + request.team + "' (one of: " + kTeams + ")");
  }
  s.team = request.team;
  s.params = LoadPassingParams(request.params, models_dir);
  s.sim = LoadSimulationParams(s.params.simulation, models_dir);
  s.field_file = ResolveModelFile(s.sim.field, DataFolder::kFields, ".", models_dir);
  s.field = LoadFieldSpec(s.field_file);
  s.kicks_file = request.kicks_file.empty()
                     ? ResolveModelFile(s.sim.kicks, DataFolder::kKicks, ".", models_dir)
                     : ResolveModelFile(request.kicks_file.string(), DataFolder::kKicks, ".",
                                        models_dir);
  s.kicks = LoadKickModel(s.kicks_file);
  if (!request.kicks_file.empty() && s.kicks.robot != "aibo_ers7") {
    throw InputError("--kicks: " + s.kicks_file.string() + ": the kick model is for robot '" +
                     s.kicks.robot + "'; the match plays AIBOs (aibo_ers7)");
  }
  s.robot = LoadRobotParams(s.sim.robot, models_dir);
  s.robot_restitution =
      LoadPhysicsParams(DataFile(models_dir, DataFolder::kPhysics, s.field.name))
          .materials.restitution.robot;
  s.config = LoadMatchConfig(request.config, models_dir, s.field, s.sim, s.robot);
  if (!request.goalie.empty()) {
    const std::optional<GoalieModel> goalie = GoalieModelNamed(request.goalie);
    if (!goalie) {
      throw InputError("--goalie: unknown goalie model '" + request.goalie +
                       "' (one of: ros2009, runswift2005)");
    }
    if (!s.config.HasGoalie()) {
      throw InputError("--goalie: " + s.config.file.string() + " has no goalie");
    }
    s.config.goalie.model = *goalie;
  }
  s.reactive = LoadReactiveParams("reactive", models_dir);
  // Kick names are checked here, before any work.
  RequireKick(s.kicks, s.config.clear_kick, s.config.file.string(), "clear_kick");
  for (std::size_t i = 0; i < s.config.clear_side_kicks.size(); ++i) {
    RequireKick(s.kicks, s.config.clear_side_kicks[i], s.config.file.string(),
                "clear_side_kicks[" + std::to_string(i) + "]");
  }
  RequireKick(s.kicks, s.reactive.shoot_kick, s.reactive.file.string(), "shoot_kick");
  if (request.team != "reactive") LoadCbrTeam(s, models_dir);
  const int count = static_cast<int>(s.config.scenarios.size());
  s.scenarios = request.scenarios;
  if (s.scenarios.empty()) {
    for (int i = 1; i <= count; ++i) s.scenarios.push_back(i);
  }
  for (std::size_t i = 0; i < s.scenarios.size(); ++i) {
    const int n = s.scenarios[i];
    if (n < 1 || n > count) {
      throw InputError("--scenarios: scenario " + std::to_string(n) + " does not exist (the " +
                       s.config.name + " configuration has 1-" + std::to_string(count) + ")");
    }
    if (std::find(s.scenarios.begin(), s.scenarios.begin() + static_cast<std::ptrdiff_t>(i), n) !=
        s.scenarios.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw InputError("--scenarios: scenario " + std::to_string(n) +
                       " is listed twice (each scenario is played once)");
    }
  }
  s.trials = request.trials > 0 ? request.trials : s.config.default_trials;
  s.mirrored = request.mirrored;
  if (s.mirrored) s.config = s.config.Mirrored();
  return s;
}

CbrTeamSetup CbrSetup(const PassingSetup& setup) {
  CbrTeamSetup c;
  c.cases = &setup.case_base.cases;
  c.skills.team = &setup.cbr;
  c.skills.retrieval = &setup.retrieval;
  c.skills.kicks = &setup.kicks;
  c.skills.aim_tolerance_rad = setup.reactive.aim_tolerance_rad;
  c.skills.dribble_turn_radps = setup.robot.dribble_turn_speed_radps;
  c.skills.release_after_s = setup.sim.ball_holding_limit_s - setup.robot.kick_launch_s;
  c.skills.control_step_s = setup.sim.control_step_s;
  c.skills.release_kick = *setup.kicks.Find(setup.reactive.shoot_kick);
  return c;
}

std::uint64_t PassingTrialKey(std::uint64_t seed, int scenario, int trial) {
  return StreamKey(seed,
                   static_cast<std::uint64_t>(scenario) * kTrialsPerScenarioKey +
                       static_cast<std::uint64_t>(trial),
                   kPassingDomain);
}

PassingResult EmptyPassingResult(const PassingSetup& setup) {
  PassingResult result;
  for (int n : setup.scenarios) {
    ScenarioTrials st;
    st.scenario = n;
    st.name = setup.config.scenarios[static_cast<std::size_t>(n - 1)].name;
    st.trials.resize(static_cast<std::size_t>(setup.trials));
    result.scenarios.push_back(std::move(st));
  }
  return result;
}

namespace {

MatchSetup MatchSetupOf(const PassingSetup& setup, const KickExecutor& executor) {
  MatchSetup match;
  match.field = &setup.field;
  match.kicks = &setup.kicks;
  match.robot = &setup.robot;
  match.sim = &setup.sim;
  match.config = &setup.config;
  match.executor = &executor;
  match.attack_sign = setup.mirrored ? -1.0 : 1.0;
  match.robot_restitution = setup.robot_restitution;
  return match;
}

// Trial `trial` of `scenario` with `team` attacking, on `match` (traced or not).
MatchTrialResult PlayTrial(const PassingSetup& setup, const std::string& team,
                           const MatchSetup& match, std::uint64_t seed, int scenario_number,
                           int trial) {
  const Scenario& scenario = setup.config.scenarios[static_cast<std::size_t>(scenario_number - 1)];
  const int n = static_cast<int>(scenario.attackers.size());
  ReactiveTeam reactive(setup.reactive, setup.field, setup.kicks, setup.robot, setup.sim, n);
  std::optional<CbrTeam> cbr;
  if (team == "cbr") cbr.emplace(CbrSetup(setup), reactive, n);
  TeamPolicy& attackers = cbr ? static_cast<TeamPolicy&>(*cbr) : reactive;
  OpponentTeam opponents(setup.config, setup.field, setup.kicks, setup.robot, setup.sim);
  return RunTrial(match, scenario, attackers, opponents,
                  PassingTrialKey(seed, scenario_number, trial));
}

}  // namespace

int ExampleTrialIndex(const PassingSetup& setup) {
  return std::min(setup.params.example_trial, setup.trials - 1);
}

MatchTrialResult PlayExampleTrial(const PassingSetup& setup, const std::string& team,
                                  const KickExecutor& executor, std::uint64_t seed,
                                  int scenario_number) {
  MatchSetup example = MatchSetupOf(setup, executor);
  example.trace_period_s = setup.params.trace_period_s;
  return PlayTrial(setup, team, example, seed, scenario_number, ExampleTrialIndex(setup));
}

std::string MatchTrialDifference(const MatchTrialResult& a, const MatchTrialResult& b) {
  // The shard form writes every number exactly (it reads back to the same bits).
  const nlohmann::json x = TrialShardJson(a), y = TrialShardJson(b);
  for (const char* key : {"outcome", "counters", "team_counters", "events", "trace"}) {
    const nlohmann::json &u = x.at(key), &v = y.at(key);
    if (u == v) continue;
    if (!u.is_array()) return key;
    if (u.size() != v.size()) {
      return std::string(key) + " (" + std::to_string(u.size()) + " against " +
             std::to_string(v.size()) + ")";
    }
    for (std::size_t i = 0; i < u.size(); ++i) {
      if (u[i] != v[i]) return std::string(key) + "[" + std::to_string(i) + "]";
    }
  }
  return "";
}

MatchTrialResult ReplayExampleTrial(const PassingSetup& setup, const std::string& team,
                                    const KickExecutor& executor, std::uint64_t seed,
                                    const ScenarioTrials& scored) {
  const std::size_t index = static_cast<std::size_t>(ExampleTrialIndex(setup));
  if (index >= scored.trials.size() || scored.trials[index].trace.empty()) {
    throw InputError("scenario " + std::to_string(scored.scenario) +
                     ": the results hold no example trial to play again");
  }
  MatchTrialResult again = PlayExampleTrial(setup, team, executor, seed, scored.scenario);
  const std::string difference = MatchTrialDifference(scored.trials[index], again);
  if (!difference.empty()) {
    throw std::logic_error("scenario " + std::to_string(scored.scenario) + ", trial " +
                           std::to_string(index) + " played again for the viewer differs from " +
                           "the scored trial in its " + difference);
  }
  return again;
}

PassingResult RunPassing(const PassingSetup& setup, const std::string& team,
                         const KickExecutor& executor, std::uint64_t seed, int threads,
                         const std::function<void(int, int)>& progress, const Shard& shard) {
  const MatchSetup match = MatchSetupOf(setup, executor);
  MatchSetup example = match;
  example.trace_period_s = setup.params.trace_period_s;

  PassingResult result = EmptyPassingResult(setup);
  const int per = setup.trials;
  const int total = per * static_cast<int>(result.scenarios.size());
  ParallelFor(
      shard.OwnedCount(total), threads,
      [&](int owned) {
        const int job = shard.Item(owned);
        ScenarioTrials& st = result.scenarios[static_cast<std::size_t>(job / per)];
        const int trial = job % per;
        const bool is_example = trial == ExampleTrialIndex(setup);
        st.trials[static_cast<std::size_t>(trial)] =
            PlayTrial(setup, team, is_example ? example : match, seed, st.scenario, trial);
      },
      progress);
  return result;
}

}  // namespace foresight
