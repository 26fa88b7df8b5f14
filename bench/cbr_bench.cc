// Speed of case retrieval (issue 13 target: <= 10 us for a case base of 136 cases on one core).
// Run:
//   build/bench/cbr_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// The case base is synthetic: solo shots and passes with 0-2 opponent scopes, their balls spread
// so that `near` of them pass the ball filter and go on to correspondence and free path.
#include <benchmark/benchmark.h>

#include <vector>

#include "cbr/retrieval.h"
#include "common/random.h"

namespace foresight {
namespace {

CaseAction Act(ActionType type) {
  CaseAction a;
  a.type = type;
  a.kick = "forward";
  return a;
}

std::vector<Case> CaseBase(int count, int near, RandomStream& rng) {
  std::vector<Case> cases;
  for (int i = 0; i < count; ++i) {
    Case c;
    c.name = "c";
    c.name += std::to_string(i);
    const bool close = i < near;
    c.p_F_ball = close ? Vec2(0.4 * rng.NextUniform() - 0.2, 0.4 * rng.NextUniform() - 0.2)
                       : Vec2(1.5 + rng.NextUniform(), 1.0 + rng.NextUniform());
    c.ball_scope = {0.5 + 0.5 * rng.NextUniform(), 0.4 + 0.4 * rng.NextUniform()};
    CaseAction shoot = Act(ActionType::kKick);
    shoot.at_goal = true;
    if (i % 2 == 0) {
      c.teammates.push_back({1, c.p_F_ball + Vec2(-0.2, 0.0), {Act(ActionType::kGetBall), shoot}});
    } else {
      CaseAction pass = Act(ActionType::kPass);
      pass.teammate = 2;
      CaseAction receive = Act(ActionType::kReceive);
      receive.teammate = 1;
      c.teammates.push_back({1, c.p_F_ball + Vec2(-0.2, 0.0), {Act(ActionType::kGetBall), pass}});
      c.teammates.push_back(
          {2, c.p_F_ball + Vec2(1.0, 1.2 * rng.NextUniform() - 0.6), {receive, shoot}});
    }
    for (int k = 0; k < i % 3; ++k) {
      c.opponents.push_back(
          {k + 1, c.p_F_ball + Vec2(0.6, 1.6 * rng.NextUniform() - 0.8), {0.3, 0.3}});
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

void BM_Retrieve136(benchmark::State& state) {
  RandomStream rng(StreamKey(13, 2));
  const std::vector<Case> cases = CaseBase(136, static_cast<int>(state.range(0)), rng);
  Problem p;
  p.p_F_ball = Vec2(0.05, -0.05);
  p.teammates = {{1, Pose2{{-0.4, 0.1}, 0.0}},
                 {2, Pose2{{0.9, 0.7}, 0.0}},
                 {3, Pose2{{0.6, -0.9}, 0.0}},
                 {4, Pose2{{-1.5, 0.0}, 0.0}}};
  p.opponents = {Vec2(0.7, 0.5), Vec2(0.65, -0.4), Vec2(2.2, 0.1)};
  const RetrievalParams params;
  RetrievalResult result;
  Retrieve(cases, p, params, &result);
  for (auto _ : state) {
    Retrieve(cases, p, params, &result);
    benchmark::DoNotOptimize(result.retrieved);
  }
  state.SetItemsProcessed(state.iterations() * 136);
}
BENCHMARK(BM_Retrieve136)->Arg(10)->Arg(40)->Arg(136);

}  // namespace
}  // namespace foresight

BENCHMARK_MAIN();
