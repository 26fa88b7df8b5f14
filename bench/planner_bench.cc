// Speed of the coarse model (the targets on one core: a plain decision <= 2 us native, an
// optimal_all decision with the rotation search <= 40 us native and <= 80 us silvermont;
// docs/PERFORMANCE.md). Run:
//   build/bench/planner_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Scenes are the shared test scenes (tests/support), so tests and benchmarks agree on them.
#include <benchmark/benchmark.h>

#include "bench/bench_scenes.h"
#include "common/random.h"
#include "models/physics_params.h"
#include "planner/coarse_planner.h"
#include "tests/support/temp_files.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

// The coarse model's contacts: the paper's inelastic stop, or rebounds (docs/PHYSICS.md, "The
// coarse model meets the contacts") with the shipped SPL restitution.
enum class Contacts { kPaper, kRebounds };

// Positions all over the field so that rolls meet posts, nets, lines and open carpet.
std::vector<Situation> Field(int count, Contacts contacts = Contacts::kPaper) {
  std::vector<Situation> situations;
  const BallPairs e =
      LoadPhysicsParams(testing::ModelsDir() / "physics" / "spl.json").materials.restitution;
  for (const testing::StateSpec& pose : bench::BenchPoses(count)) {
    situations.push_back(testing::MakeSituation(pose, bench::BenchObstacles()));
    if (contacts == Contacts::kRebounds) {
      situations.back().evaluation.rebounds = {true, 8, e.post, e.net, e.robot};
    }
  }
  return situations;
}

// Samples of the decision's hot path: one candidate (kick, rotation) over 30 drawn samples,
// as the rotation search evaluates them (roll, first contact, classification, value).
void BM_HypothesisSamples(benchmark::State& state, Contacts contacts) {
  const std::vector<Situation> situations = Field(16, contacts);
  std::vector<CoarsePlanner> planners(situations.begin(), situations.end());
  std::vector<CoarseActionEvaluator> evaluators;
  for (const CoarsePlanner& p : planners) evaluators.push_back(p.MakeEvaluator(30, 1));
  std::uint64_t index = 0;
  double sink = 0.0;
  for (auto _ : state) {
    const double rho = static_cast<double>(index % 72) * (kPi / 36.0) - kPi;
    sink += evaluators[index & 15].Evaluate(static_cast<int>(index % 3), rho).utility;
    ++index;
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations() * 30);
}
BENCHMARK_CAPTURE(BM_HypothesisSamples, paper, Contacts::kPaper);
BENCHMARK_CAPTURE(BM_HypothesisSamples, rebounds, Contacts::kRebounds);

// One sample from scratch through the seam: draw the state and the kick noise (7 normals),
// place the ball, roll, classify, value.
void BM_FreshSample(benchmark::State& state) {
  const std::vector<Situation> situations = Field(16);
  std::vector<CoarsePlanner> planners(situations.begin(), situations.end());
  std::uint64_t index = 0;
  double sink = 0.0;
  for (auto _ : state) {
    const CoarsePlanner& planner = planners[index & 15];
    const DrawnSample sample = DrawSample(planner.situation().state, 1, index);
    const int kick = static_cast<int>(index % 3);
    const Outcome o = planner.simulator().Simulate(
        sample.state, MakeAction(planner.situation().kicks, kick, 0.0, sample));
    sink += o.category == Category::kInfield ? planner.value().Value(o.p_F_rest) : 1.0;
    ++index;
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FreshSample);

// The 30 samples of a decision drawn into kept storage (7 normals each, the ball placed).
void BM_DrawSamples(benchmark::State& state) {
  const std::vector<Situation> situations = Field(16);
  std::vector<DrawnSample> samples;
  std::uint64_t seed = 0;
  for (auto _ : state) {
    DrawSamples(situations[seed & 15].state, seed, 30, samples);
    benchmark::DoNotOptimize(samples.data());
    ++seed;
  }
}
BENCHMARK(BM_DrawSamples);

// A whole decision as a robot's cycle makes it: the samples drawn for the pose and seed into
// the evaluator's storage (kept between cycles), the strategy, the result into a kept Decision.
void BM_Decision(benchmark::State& state, Strategy strategy, Contacts contacts) {
  const std::vector<Situation> situations = Field(16, contacts);
  std::vector<CoarsePlanner> planners(situations.begin(), situations.end());
  std::vector<CoarseActionEvaluator> evaluators;
  for (const CoarsePlanner& p : planners) evaluators.push_back(p.MakeEvaluator(30, 0));
  Decision d;
  ReserveDecision(d, 3);
  std::uint64_t seed = 0;
  long long hypotheses = 0;
  for (auto _ : state) {
    const std::size_t scene = seed & 15;
    planners[scene].Decide(situations[scene].state, strategy, 30, seed, evaluators[scene], d);
    hypotheses += d.evaluations;
    benchmark::DoNotOptimize(d.kick_index);
    ++seed;
  }
  state.counters["hypotheses"] =
      benchmark::Counter(static_cast<double>(hypotheses), benchmark::Counter::kAvgIterations);
}
// naoth: the plain decision, 3 kicks + none at their current rotation, 30 samples each.
BENCHMARK_CAPTURE(BM_Decision, plain_naoth, Strategy::kNaoth, Contacts::kPaper)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Decision, fast, Strategy::kFast, Contacts::kPaper)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Decision, optimal_all, Strategy::kOptimalAll, Contacts::kPaper)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Decision, optimal_value, Strategy::kOptimalValue, Contacts::kPaper)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Decision, optimal_all_rebounds, Strategy::kOptimalAll, Contacts::kRebounds)
    ->Unit(benchmark::kMicrosecond);

// The same through CoarsePlanner::Decide(strategy, samples, seed), which makes a fresh evaluator
// and Decision each time (about 15 heap allocations), against a robot that keeps one evaluator
// and one Decision (BM_Decision).
void BM_DecisionFresh(benchmark::State& state, Strategy strategy) {
  const std::vector<Situation> situations = Field(16);
  std::vector<CoarsePlanner> planners(situations.begin(), situations.end());
  std::uint64_t seed = 0;
  for (auto _ : state) {
    const Decision d = planners[seed & 15].Decide(strategy, 30, seed);
    benchmark::DoNotOptimize(d.kick_index);
    ++seed;
  }
}
BENCHMARK_CAPTURE(BM_DecisionFresh, plain_naoth, Strategy::kNaoth)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_DecisionFresh, optimal_all, Strategy::kOptimalAll)
    ->Unit(benchmark::kMicrosecond);

// Building the per-situation planner (scene and the value's normalisation over the field).
void BM_PlannerSetup(benchmark::State& state) {
  const std::vector<Situation> situations = Field(1);
  for (auto _ : state) {
    CoarsePlanner planner(situations[0]);
    benchmark::DoNotOptimize(planner.value().potential_max());
  }
}
BENCHMARK(BM_PlannerSetup)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace foresight

BENCHMARK_MAIN();
