// Speed of the physics ground truth (the targets per core: a free roll of 5 m >= 1000
// trials/s, a complete NAO kick trial until the ball rests >= 50 trials/s, near-linear scaling
// with cores). Run:
//   build/bench/physics_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// ->Threads(n) runs n independent trial loops at once, so items/s at 2 threads over items/s at
// 1 thread is the speed-up on two cores. Scenes are the shared test scenes (tests/physics).
#include <benchmark/benchmark.h>

#include <cmath>

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

// The same kick by a NAO standing on its own feet (floating base): the weight shift is settled
// once when the scene is made (not timed), each trial restores it, kicks, stands through the
// rest of the motion and its settle time, and the ball rolls to rest.
void BM_NaoKickTrialFloating(benchmark::State& state) {
  static const auto data = [] {
    auto d = testing::LoadPhysicsFixture("spl", false, "nao");
    d->params.robot.base = RobotBase::kFloating;
    return d;
  }();
  static const KickModel kicks = LoadKickModel(testing::ModelsDir() / "kicks" / "nao.json");
  const DrawnState drawn{Pose2{Vec2(-1.0, 0.0), 0.0}, Vec2(-0.8, 0.0)};
  static const PhysicsSimulator simulator(testing::SceneOf(*data, {}, drawn.p_F_ball), kicks);
  std::uint64_t i = 0;
  for (auto _ : state) {
    ConcreteAction action;
    action.kick_index = 0;
    action.stream = StreamKey(2, i++);
    benchmark::DoNotOptimize(simulator.Simulate(drawn, action));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_NaoKickTrialFloating)
    ->Unit(benchmark::kMillisecond)
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime();

}  // namespace
}  // namespace foresight

BENCHMARK_MAIN();
