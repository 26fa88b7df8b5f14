// Speed of the CBR team's reasoning: retrieval and a whole decision cycle's reasoning time per
// robot, to compare with the AIBO's time budget. Run (docs/PERFORMANCE.md):
//   taskset -c 1 build/bench/cbr_team_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
// BM_CoordinatorStep/<timing>: the costliest step of a robot: it is the selector and the
//   closest retriever, so in one Decide it starts a cycle, retrieves from the shipped case base
//   (the dg scenario 1 problem: 2 teammates, defender and goalie) and adopts the case; timing 1
//   adds the timing-aware pass check. The team object is built inside the loop (two robots'
//   state: a few hundred bytes) since a retrieval step happens once per cycle.
// BM_CbrTrial/<scenario>: whole DG trials of the CBR team (coarse kicks) against the shipped
//   opponents; counters: robot decisions per second and trials per second (compare with
//   match_bench's BM_Trial for the reactive team).
#include <benchmark/benchmark.h>

#include <cmath>

#include "common/random.h"
#include "experiments/passing.h"
#include "match/opponent_team.h"
#include "models/model_paths.h"

namespace foresight {
namespace {

const PassingSetup& Setup() {
  static const PassingSetup setup = [] {
    PassingRequest request;
    request.config = "dg";
    request.team = "cbr";
    return LoadPassingSetup(request, DefaultModelsDir());
  }();
  return setup;
}

class StandStill final : public TeamPolicy {
 public:
  RobotCommand Decide(const Perception&) override { return {}; }
};

void BM_CoordinatorStep(benchmark::State& state) {
  PassingSetup setup = Setup();
  setup.cbr.pass_timing.enabled = state.range(0) != 0;
  const Scenario& scenario = setup.config.scenarios[0];
  StandStill fallback;
  const CbrTeamSetup team_setup = CbrSetup(setup);
  // Robot 1's belief has arrived: robot 0 can choose the coordinator at once.
  TeamMessage belief = MakeCbrMessage(CbrMessageKind::kBelief, 0, scenario.p_F_ball,
                                      (scenario.p_F_ball - scenario.attackers[1].p_F).norm());
  belief.sender = 1;
  Perception p;
  p.time_s = 0.04;
  p.self = 0;
  p.pose = scenario.attackers[0];
  p.p_F_ball = scenario.p_F_ball;
  p.teammates = scenario.attackers;
  p.opponents = scenario.opponents;
  p.inbox = std::span<const TeamMessage>(&belief, 1);
  double retrieved = 0.0;
  for (auto _ : state) {
    CbrTeam team(team_setup, fallback, 2);
    const RobotCommand c = team.Decide(p);
    benchmark::DoNotOptimize(c.kind);
    retrieved += team.PhaseOf(0) != CbrPhase::kIdle;
  }
  state.counters["retrieved_share"] =
      benchmark::Counter(retrieved / static_cast<double>(state.iterations()));
}
BENCHMARK(BM_CoordinatorStep)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_CbrTrial(benchmark::State& state) {
  const PassingSetup& setup = Setup();
  const CoarseKickExecutor executor(setup.field, setup.kicks.rolling_deceleration_mps2);
  const MatchSetup match{&setup.field, &setup.kicks, &setup.robot, &setup.sim,
                         &setup.config, &executor,   1.0,          0.0};
  const Scenario& scenario = setup.config.scenarios[static_cast<std::size_t>(state.range(0) - 1)];
  const CbrTeamSetup team_setup = CbrSetup(setup);
  double decisions = 0.0, trials = 0.0;
  std::uint64_t key = 0;
  for (auto _ : state) {
    ReactiveTeam reactive(setup.reactive, setup.field, setup.kicks, setup.robot, setup.sim, 2);
    CbrTeam attackers(team_setup, reactive, 2);
    OpponentTeam opponents(setup.config, setup.field, setup.kicks, setup.robot,
                           setup.sim);
    const MatchTrialResult r = RunTrial(match, scenario, attackers, opponents, StreamKey(1, key++));
    benchmark::DoNotOptimize(r.outcome);
    decisions += 2.0 * std::round(r.counters.time_s / setup.sim.control_step_s);
    trials += 1.0;
  }
  state.counters["decisions_per_s"] = benchmark::Counter(decisions, benchmark::Counter::kIsRate);
  state.counters["trials_per_s"] = benchmark::Counter(trials, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CbrTrial)->DenseRange(1, 4)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace foresight

BENCHMARK_MAIN();
