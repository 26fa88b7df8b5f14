// Speed of the match simulator (the target: a whole DG table, 4 scenarios x 500 trials for
// one team, in well under a minute on 2 cores). Run (docs/PERFORMANCE.md):
//   taskset -c 1 build/bench/match_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
// BM_Trial/<config>/<scenario>: whole trials of the reactive team against the shipped
// opponents, trial keys cycled; counters: control steps per second (all robots decide and move
// once per step) and trials per second.
#include <benchmark/benchmark.h>

#include <cmath>

#include "common/random.h"
#include "match/match.h"
#include "match/opponent_team.h"
#include "match/reactive_team.h"
#include "models/model_paths.h"

namespace foresight {
namespace {

struct Loaded {
  explicit Loaded(const std::string& config_name)
      : models(DefaultModelsDir()),
        sim(LoadSimulationParams("simulation", models)),
        field(LoadFieldSpec(DataFile(models, DataFolder::kFields, sim.field))),
        kicks(LoadKickModel(DataFile(models, DataFolder::kKicks, sim.kicks))),
        robot(LoadRobotParams(sim.robot, models)),
        config(LoadMatchConfig(config_name, models, field, sim, robot)),
        reactive(LoadReactiveParams("reactive", models)),
        executor(field, kicks.rolling_deceleration_mps2) {}
  std::filesystem::path models;
  SimulationParams sim;
  FieldSpec field;
  KickModel kicks;
  RobotParams robot;
  MatchConfig config;
  ReactiveParams reactive;
  CoarseKickExecutor executor;
};

void BM_Trial(benchmark::State& state, const char* config_name) {
  static const Loaded dg("dg"), two_d("2d");
  const Loaded& l = std::string(config_name) == "dg" ? dg : two_d;
  const MatchSetup setup{&l.field, &l.kicks, &l.robot, &l.sim, &l.config, &l.executor, 1.0, 0.0};
  const Scenario& scenario = l.config.scenarios[static_cast<std::size_t>(state.range(0) - 1)];
  double steps = 0.0, trials = 0.0;
  std::uint64_t key = 0;
  for (auto _ : state) {
    ReactiveTeam attackers(l.reactive, l.field, l.kicks, l.robot, l.sim, 2);
    OpponentTeam opponents(l.config, l.field, l.kicks, l.robot, l.sim);
    const MatchTrialResult r = RunTrial(setup, scenario, attackers, opponents, StreamKey(1, key++));
    benchmark::DoNotOptimize(r.outcome);
    steps += std::round(r.counters.time_s / l.sim.control_step_s);
    trials += 1.0;
  }
  state.counters["steps_per_s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
  state.counters["trials_per_s"] = benchmark::Counter(trials, benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_Trial, dg, "dg")->DenseRange(1, 4)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Trial, 2d, "2d")->DenseRange(1, 4)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace foresight

BENCHMARK_MAIN();
