// The passing experiment (Ros et al. 2009, sec. 5.2): two attackers played by a team (the
// reactive baseline, match/reactive_team.h, or the CBR team, cbr/cbr_team.h, whose default
// behaviour is the reactive team) against the opponents of one configuration (DG or 2D) from
// each of the four scenarios, N trials each, in the match simulator (match/match.h).
//
// Trial i of scenario s draws everything from StreamKey(seed, s * kTrialsPerScenarioKey + i,
// kPassingDomain): the key does not depend on the team, so every team meets the same random
// numbers (common random numbers: the next issue's comparison is paired), nor on the thread.
// The experiment file (models/experiments/passing.json) names the simulation file and holds the
// report's figures and the paper's (for the scorecard of --team both): the confidence of the intervals, the example trial and how it is drawn.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cbr/case_base.h"
#include "cbr/cbr_team.h"
#include "cbr/retrieval_params.h"
#include "cbr/team_params.h"
#include "common/shard.h"
#include "match/match.h"
#include "match/reactive_team.h"
#include "models/field_spec.h"

namespace foresight {

inline constexpr std::uint64_t kPassingDomain = 0x7061'7373'696eULL;  // "passin"
inline constexpr std::uint64_t kTrialsPerScenarioKey = 1ULL << 32;

struct PassingParams {
  std::filesystem::path file;
  std::string simulation;  // name of the simulation file in MODELS/match
  double confidence = 0.0;
  int example_trial = 0;            // the trial of each scenario recorded and drawn (Fig. 13)
  double trace_period_s = 0.0;      // how often the example trial is recorded
  double step_mark_period_s = 0.0;  // numbered marks on the example's paths this often
  // An opponent's kick counts as having moved the ball (experiments/passing_causes.h) from this.
  double kick_moved_min_m = 0.0;
  std::string paper_tables;  // the paper's figures in MODELS/experiments (experiments/paper_tables.h)

  void Validate() const;
};
PassingParams LoadPassingParams(const std::string& reference,
                                const std::filesystem::path& models_dir);

// How the match's robot holds the ball under its rules (cbr/kick_race.h): grab, dribble and turn
// with the ball, the holding limit less the launch (the teams start the kick then), the launch.
HoldParams HoldParamsFor(const RobotParams& robot, const SimulationParams& sim);
// The same for the passing experiment's default simulation ("passing"): the robot and rules the
// shipped cases are played under, which `foresight cbr check` judges them by.
HoldParams DefaultHoldParams(const std::filesystem::path& models_dir);
// The home regions of the opponents of match configuration `config` ("dg", "2d" or a file) under
// the passing experiment's default simulation, in the configuration's order.
std::vector<FieldBox> DefaultOpponentRegions(const std::string& config,
                                             const std::filesystem::path& models_dir);

// Every input of one run, loaded and checked.
struct PassingSetup {
  PassingParams params;
  SimulationParams sim;
  FieldSpec field;
  std::filesystem::path field_file;
  KickModel kicks;
  std::filesystem::path kicks_file;
  RobotParams robot;
  // The ball-robot restitution of the field's physics file (materials.restitution.ball_robot),
  // the one number physics and the coarse rebounds also use.
  double robot_restitution = 0.0;
  MatchConfig config;  // mirrored when `mirrored`
  std::string team;                // as requested: "reactive", "cbr" or "both"
  std::vector<std::string> teams;  // the teams to play, in report order ("cbr", "reactive")
  ReactiveParams reactive;
  // The CBR team (loaded when it plays): its parameters, retrieval's and the case base.
  CbrTeamParams cbr;
  RetrievalParams retrieval;
  LoadedCaseBase case_base;
  std::vector<int> scenarios;  // 1-based scenario numbers to play, ascending
  int trials = 0;              // per scenario
  bool mirrored = false;       // the attackers attack the goal at -x
};

// The team names `--team` accepts.
std::string PassingTeamNames();

struct PassingRequest {
  std::string params = "passing";
  std::string config;  // "dg", "2d" or a file
  std::string team = "reactive";
  std::vector<int> scenarios;  // empty: all of the config's
  int trials = 0;              // 0: the config's default
  bool mirrored = false;
  std::filesystem::path kicks_file;  // replaces the simulation file's kick model when not empty
  std::string goalie;  // replaces the configuration's goalie model when not empty (GoalieModelName)
};
PassingSetup LoadPassingSetup(const PassingRequest& request,
                              const std::filesystem::path& models_dir);

struct ScenarioTrials {
  int scenario = 0;  // 1-based
  std::string name;
  std::vector<MatchTrialResult> trials;  // trial i at index i; the example one with its trace
};

struct PassingResult {
  std::vector<ScenarioTrials> scenarios;
};

std::uint64_t PassingTrialKey(std::uint64_t seed, int scenario, int trial);

// The CBR team's setup from the loaded inputs: the low-level skills are the reactive team's
// (its aim tolerance) and the match's (the ball-holding rule), as in the paper (sec. 5.3).
CbrTeamSetup CbrSetup(const PassingSetup& setup);

// The scenarios of `setup` with their names and setup.trials empty trials each.
PassingResult EmptyPassingResult(const PassingSetup& setup);

// Plays every trial with `team` (one of setup.teams) attacking and `executor` carrying out the
// kicks; progress(done, total) counts trials. With a shard other than the whole run,
// only the trials it owns are played, numbered scenario by scenario (trial i of the k-th
// scenario is k * setup.trials + i); the others stay empty: experiments/passing_shard.h merges
// the shards. A trial's random numbers and whether it is traced never depend on the shard.
PassingResult RunPassing(const PassingSetup& setup, const std::string& team,
                         const KickExecutor& executor, std::uint64_t seed, int threads,
                         const std::function<void(int, int)>& progress = {},
                         const Shard& shard = {});

// Which trial of every scenario is the traced example (the parameters' example_trial).
int ExampleTrialIndex(const PassingSetup& setup);
// Plays the example trial of the scenario numbered `scenario_number` again, traced, exactly as
// RunPassing played it (the same random numbers): its kicks go to `executor`, one at a time in
// the match's order (the 3D viewer records them through it, app/passing_view.h).
MatchTrialResult PlayExampleTrial(const PassingSetup& setup, const std::string& team,
                                  const KickExecutor& executor, std::uint64_t seed,
                                  int scenario_number);
// PlayExampleTrial of the scenario of `scored` (RunPassing's result for it), checked against
// the example trial the run scored: std::logic_error naming the first difference unless the
// replay is the same trial bit for bit (outcome, counters, events, trace), so a viewer never
// shows a trial other than the one scored. InputError when `scored` holds no example trial.
MatchTrialResult ReplayExampleTrial(const PassingSetup& setup, const std::string& team,
                                    const KickExecutor& executor, std::uint64_t seed,
                                    const ScenarioTrials& scored);
// Where two trials differ ("" when they are the same bit for bit): "outcome", "counters",
// "team_counters", "events[3]", "trace[120]" or "events (12 against 13)".
std::string MatchTrialDifference(const MatchTrialResult& a, const MatchTrialResult& b);

}  // namespace foresight
