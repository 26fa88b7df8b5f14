// Speed of the physics ground truth (the targets per core: a free roll of 5 m >= 1000
// trials/s, a complete NAO kick trial until the ball rests >= 50 trials/s, near-linear scaling
// with cores). Run:
//   build/bench/physics_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// ->Threads(n) runs n independent trial loops at once, so items/s at 2 threads over items/s at
// 1 thread is the speed-up on two cores. Scenes are the shared test scenes (tests/physics).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <utility>

#include "common/random.h"
#include "models/kick_model.h"
#include "physics/physics_simulator.h"
#include "tests/support/physics_test_scenes.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

// A ball launched so that it rolls 5 m on open carpet (v = sqrt(2 a 5)), in directions within
// +-30 degrees of the x axis from (-2.5, 0): clear of goals, so the large time step applies.
void BM_FreeRoll5m(benchmark::State& state) {
  static const auto data = testing::LoadPhysicsFixture("spl", false);
  const PhysicsScene scene = testing::SceneOf(*data);
  const double a = data->params.carpet.rolling_deceleration_mps2;
  const double speed = std::sqrt(2.0 * a * 5.0);
  std::uint64_t i = 0;
  for (auto _ : state) {
    const double heading = (static_cast<double>(i % 13) - 6.0) * (kPi / 36.0);
    const BallState start = RollingBall(Vec2(-2.5, 0.0), data->field.ball.radius_m, speed, heading);
    benchmark::DoNotOptimize(RunRollTrial(scene, start, StreamKey(1, i++), false));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FreeRoll5m)->Unit(benchmark::kMillisecond)->Threads(1)->Threads(2)->UseRealTime();

// A whole NAO forward kick from midfield: the robot kicks, the ball launches and rolls to rest;
// with scene_rate_hz > 0 the trial is also recorded for the 3D viewer (physics/scene_recorder.h:
// every link's pose per frame, the contacts per step).
void NaoKickTrials(benchmark::State& state, double scene_rate_hz) {
  static const auto data = testing::LoadPhysicsFixture("spl", false, "nao");
  static const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "nao.json");
  const DrawnState drawn{Pose2{Vec2(-1.0, 0.0), 0.0}, Vec2(-0.8, 0.0)};
  const PhysicsSimulator simulator(testing::SceneOf(*data, {}, drawn.p_F_ball), kicks);
  std::uint64_t i = 0;
  for (auto _ : state) {
    ConcreteAction action;
    action.kick_index = 0;
    action.stream = StreamKey(2, i++);
    if (scene_rate_hz > 0.0) {
      benchmark::DoNotOptimize(simulator.Run(drawn, action, false, scene_rate_hz));
    } else {
      benchmark::DoNotOptimize(simulator.Simulate(drawn, action));
    }
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_NaoKickTrial(benchmark::State& state) { NaoKickTrials(state, 0.0); }
BENCHMARK(BM_NaoKickTrial)->Unit(benchmark::kMillisecond)->Threads(1)->Threads(2)->UseRealTime();

// The same trials recorded at 100 frames per second (`simulate --view`'s default).
void BM_NaoKickTrialRecorded(benchmark::State& state) { NaoKickTrials(state, 100.0); }
BENCHMARK(BM_NaoKickTrialRecorded)->Unit(benchmark::kMillisecond)->Threads(1)->UseRealTime();

// A robot's kick trials from midfield on `base`, made once per benchmark (its floating weight
// shift is settled when the scene is made, not timed).
struct KickBench {
  std::unique_ptr<testing::PhysicsFixtureData> data;
  KickModel kicks;
  DrawnState drawn{Pose2{Vec2(-1.0, 0.0), 0.0}, Vec2(-0.8, 0.0)};
  PhysicsSimulator simulator;
  KickBench(std::unique_ptr<testing::PhysicsFixtureData> d, const char* kicks_file)
      : data(std::move(d)),
        kicks(LoadKickModel(testing::ModelsDir() / "kicks" / kicks_file)),
        simulator(testing::SceneOf(*data, {}, drawn.p_F_ball), kicks) {}
};

std::unique_ptr<testing::PhysicsFixtureData> OnBase(const char* field, const char* robot,
                                                    RobotBase base) {
  auto data = testing::LoadPhysicsFixture(field, false, robot);
  data->params.robot.base = base;
  return data;
}

// Kick 0 (`forward`): each trial restores the settled shift on the floating base, kicks, is
// watched for a fall until the robot has stood its settle time after its motion (or stands
// still: physics/fall_watch.h), and the ball rolls to rest.
void KickTrials(benchmark::State& state, const KickBench& bench) {
  std::uint64_t i = 0;
  for (auto _ : state) {
    ConcreteAction action;
    action.kick_index = 0;
    action.stream = StreamKey(2, i++);
    benchmark::DoNotOptimize(bench.simulator.Simulate(bench.drawn, action));
  }
  state.SetItemsProcessed(state.iterations());
}

// The NAO kick of BM_NaoKickTrial standing on its own feet.
void BM_NaoKickTrialFloating(benchmark::State& state) {
  static const KickBench bench(OnBase("spl", "nao", RobotBase::kFloating), "nao.json");
  KickTrials(state, bench);
}
BENCHMARK(BM_NaoKickTrialFloating)
    ->Unit(benchmark::kMillisecond)
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime();

// The AIBO's `forward` paw kick on the four-legged field, bolted and on its own paws.
void BM_AiboKickTrial(benchmark::State& state) {
  static const KickBench bench(OnBase("four_legged", "aibo_ers7", RobotBase::kFixed),
                               "aibo_ers7.json");
  KickTrials(state, bench);
}
BENCHMARK(BM_AiboKickTrial)->Unit(benchmark::kMillisecond)->Threads(1)->UseRealTime();
void BM_AiboKickTrialFloating(benchmark::State& state) {
  static const KickBench bench(OnBase("four_legged", "aibo_ers7", RobotBase::kFloating),
                               "aibo_ers7.json");
  KickTrials(state, bench);
}
BENCHMARK(BM_AiboKickTrialFloating)->Unit(benchmark::kMillisecond)->Threads(1)->UseRealTime();

}  // namespace
}  // namespace foresight

BENCHMARK_MAIN();
