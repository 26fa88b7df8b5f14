// Speed of case retrieval (the targets, one core: <= 10 us for the 136 cases and a
// 2-teammate, 2-opponent problem; sub-linear with the ball-scope index, <= 100 us at 100,000
// cases). Run (docs/PERFORMANCE.md):
//   taskset -c 1 build/bench/cbr_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
// BM_Retrieve136: a synthetic case base of solo shots and passes with 0-2 opponent scopes, their
// balls spread so that `near` of them pass the ball filter and go on to correspondence and free
// path (136: the worst case), and a 4-teammate, 3-opponent problem.
// BM_Shipped: the shipped case base (all 136 cases, both goals, as the caller passes them, or
// the 68 of the problem's goal) over 256 random 2-vs-2 attacks cycled (the typical case).
// BM_ShippedWorst: the 136 synthetic cases all passing the ball filter, a 2-vs-2 problem.
// BM_Synthetic: SyntheticCases (cbr/synthetic_cases.h) from the shipped cases for cyan, 10,000
// or 100,000, over the same 256 attacks, without (0) and with (1) the BallScopeIndex.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "cbr/ball_scope_index.h"
#include "cbr/case_base.h"
#include "cbr/retrieval.h"
#include "cbr/similarity.h"
#include "cbr/synthetic_cases.h"
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
    const double u = rng.NextUniform();  // one draw per statement: argument order is unspecified
    const double v = rng.NextUniform();
    c.p_F_ball = close ? Vec2(0.4 * u - 0.2, 0.4 * v - 0.2) : Vec2(1.5 + u, 1.0 + v);
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

// Random 2-vs-2 attacks for the team defending cyan (like cbr/coverage.h's): the ball over
// x in [-2.0, 2.6], |y| <= 1.6; teammate 1 up to 0.5 m behind it, teammate 2 in a box of
// +-1.5 x +-1.0 m around it;
// a defender and a goalie in their DG home regions.
std::vector<Problem> Attacks(int count) {
  RandomStream rng(StreamKey(13, 3));
  const auto u = [&](double lo, double hi) { return lo + (hi - lo) * rng.NextUniform(); };
  const auto field = [](const Vec2& p) {
    return Vec2(std::clamp(p.x(), -2.7, 2.7), std::clamp(p.y(), -1.8, 1.8));
  };
  const auto box = [&](double x_lo, double x_hi, double y_lo, double y_hi) {
    const double x = u(x_lo, x_hi);  // x, then y: sequenced
    return Vec2(x, u(y_lo, y_hi));
  };
  std::vector<Problem> problems;
  for (int i = 0; i < count; ++i) {
    Problem p;
    p.p_F_ball = box(-2.0, 2.6, -1.6, 1.6);
    const Vec2 behind = box(-0.5, 0.0, -0.3, 0.3);
    const Vec2 support = box(-1.5, 1.5, -1.0, 1.0);
    p.teammates = {{1, Pose2{field(p.p_F_ball + behind), 0.0}},
                   {2, Pose2{field(p.p_F_ball + support), 0.0}}};
    const Vec2 defender = box(0.3, 2.0, -1.3, 1.3);
    p.opponents = {defender, box(2.05, 2.6, -0.65, 0.65)};
    problems.push_back(std::move(p));
  }
  return problems;
}

const LoadedCaseBase& Shipped() {
  static const LoadedCaseBase base = LoadCaseBase(DefaultCaseBasePath(DefaultModelsDir()));
  return base;
}

// The shipped cases for cyan (68), or for both goals (136): retrieval then also rejects the other
// goal's half, as a caller that does not index by goal would make it.
std::vector<Case> ShippedCases(bool both_goals) {
  const auto cyan = Shipped().cases.Defending(DefendingGoal::kCyan);
  std::vector<Case> cases(cyan.begin(), cyan.end());
  if (both_goals) {
    const auto yellow = Shipped().cases.Defending(DefendingGoal::kYellow);
    cases.insert(cases.end(), yellow.begin(), yellow.end());
  }
  return cases;
}

void BM_Shipped(benchmark::State& state) {
  const std::vector<Case> cases = ShippedCases(state.range(0) == 136);
  const std::vector<Problem> problems = Attacks(256);
  const RetrievalParams params;
  RetrievalResult result;
  std::size_t i = 0, retrieved = 0;
  for (auto _ : state) {
    Retrieve(cases, problems[i++ & 255], params, &result);
    retrieved += result.retrieved ? 1 : 0;
    benchmark::DoNotOptimize(result.retrieved);
  }
  state.counters["retrieved"] = static_cast<double>(retrieved) / state.iterations();
}
BENCHMARK(BM_Shipped)->Arg(68)->Arg(136);

// The shipped cases' worst 2-vs-2 problem: the ball where the most cases of one goal pass the
// ball filter (a 5 cm grid), teammate 1 0.3 m behind it and teammate 2 and the two opponents
// where the most cases go on to the free-path test or further (a 0.25 m grid within 1.5 m of
// the ball for teammate 2; the defender and goalie from a coarse grid of their home regions).
Problem ShippedWorstProblem(std::span<const Case> cases, const RetrievalParams& params) {
  Problem p;
  int best = -1;
  Vec2 ball(0.0, 0.0);
  best = -1;
  for (double x = -2.6; x <= 2.6; x += 0.05) {
    for (double y = -1.7; y <= 1.7; y += 0.05) {
      p.p_F_ball = Vec2(x, y);
      int in = 0;
      for (const Case& c : cases) in += BallSimilarity(p, c) > params.thr_ball ? 1 : 0;
      if (in > best) {
        best = in;
        ball = p.p_F_ball;
      }
    }
  }
  p.p_F_ball = ball;
  const auto deep = [&](const Problem& q) {
    int n = 0;
    for (const CaseEvaluation& e : Retrieve(cases, q, params).evaluations) {
      n += e.verdict == Verdict::kCandidate || e.verdict == Verdict::kPathBlocked ? 1 : 0;
    }
    return n;
  };
  p.teammates = {{1, Pose2{ball + Vec2(-0.3, 0.0), 0.0}}, {2, Pose2{ball, 0.0}}};
  p.opponents = {Vec2(1.0, 0.0), Vec2(2.4, 0.0)};
  best = -1;
  Vec2 mate = ball;
  for (double dx = -1.5; dx <= 1.5; dx += 0.25) {
    for (double dy = -1.5; dy <= 1.5; dy += 0.25) {
      p.teammates[1].pose.p_F = ball + Vec2(dx, dy);
      const int n = deep(p);
      if (n > best) {
        best = n;
        mate = p.teammates[1].pose.p_F;
      }
    }
  }
  p.teammates[1].pose.p_F = mate;
  best = -1;
  std::vector<Vec2> worst = p.opponents;
  for (double dx = 0.3; dx <= 2.0; dx += 0.34) {
    for (double dy = -1.3; dy <= 1.3; dy += 0.52) {
      for (double gy = -0.6; gy <= 0.6; gy += 0.3) {
        p.opponents = {Vec2(dx, dy), Vec2(2.3, gy)};
        const int n = deep(p);
        if (n > best) {
          best = n;
          worst = p.opponents;
        }
      }
    }
  }
  p.opponents = worst;
  return p;
}

void BM_ShippedWorst(benchmark::State& state) {
  const std::vector<Case> cases = ShippedCases(true);
  const auto cyan = Shipped().cases.Defending(DefendingGoal::kCyan);
  const RetrievalParams params;
  const Problem p = ShippedWorstProblem(cyan, params);
  RetrievalResult result;
  Retrieve(cases, p, params, &result);
  int in_scope = 0, deep = 0;
  for (const CaseEvaluation& e : result.evaluations) {
    in_scope += e.verdict != Verdict::kOtherGoal && e.verdict != Verdict::kBallOutOfScope;
    deep += e.verdict == Verdict::kCandidate || e.verdict == Verdict::kPathBlocked;
  }
  for (auto _ : state) {
    Retrieve(cases, p, params, &result);
    benchmark::DoNotOptimize(result.retrieved);
  }
  state.counters["in_scope"] = in_scope;
  state.counters["to_path"] = deep;
  state.counters["candidates"] = static_cast<double>(result.ranking.size());
}
BENCHMARK(BM_ShippedWorst);

// An upper bound no real case base of 136 reaches (half of it is for the other goal): 136
// synthetic cases for the problem's goal, all passing the ball filter, a 2-vs-2 problem.
void BM_SyntheticWorst136(benchmark::State& state) {
  RandomStream rng(StreamKey(13, 2));
  const std::vector<Case> cases = CaseBase(136, 136, rng);
  Problem p;
  p.p_F_ball = Vec2(0.05, -0.05);
  p.teammates = {{1, Pose2{{-0.4, 0.1}, 0.0}}, {2, Pose2{{0.9, 0.7}, 0.0}}};
  p.opponents = {Vec2(0.7, 0.5), Vec2(2.2, 0.1)};
  const RetrievalParams params;
  RetrievalResult result;
  Retrieve(cases, p, params, &result);
  for (auto _ : state) {
    Retrieve(cases, p, params, &result);
    benchmark::DoNotOptimize(result.retrieved);
  }
  state.counters["candidates"] = static_cast<double>(result.ranking.size());
}
BENCHMARK(BM_SyntheticWorst136);

void BM_Synthetic(benchmark::State& state) {
  SyntheticCaseSpec spec;
  spec.count = static_cast<int>(state.range(0));
  // range(2) = 1: the scopes shrink with the density, sqrt(68 / count), so a ball lies in as
  // few scopes as with the shipped cases (3 on average for these attacks); 0: the shipped
  // scopes, so a ball lies in about 4% of all the cases (420 of 10,000) whatever the index.
  if (state.range(2) != 0) spec.scope_scale = std::sqrt(68.0 / spec.count);
  const std::vector<Case> cases =
      SyntheticCases(Shipped().cases.Defending(DefendingGoal::kCyan), Shipped().kick_mirrors, spec);
  const bool indexed = state.range(1) != 0;
  const RetrievalParams params;
  const BallScopeIndex index(cases, params.thr_ball);
  const std::vector<Problem> problems = Attacks(256);
  RetrievalResult result;
  result.evaluations.reserve(cases.size());
  result.ranking.reserve(cases.size());
  std::size_t i = 0, evaluated = 0, in_scope = 0;
  for (auto _ : state) {
    const Problem& p = problems[i++ & 255];
    if (indexed) {
      Retrieve(cases, index, p, params, &result);
    } else {
      Retrieve(cases, p, params, &result);
    }
    evaluated += indexed ? index.Query(p.p_F_ball).size() : cases.size();
    for (const CaseEvaluation& e : result.evaluations) {
      in_scope += e.verdict != Verdict::kBallOutOfScope ? 1 : 0;
    }
    benchmark::DoNotOptimize(result.retrieved);
  }
  state.counters["evaluated"] = static_cast<double>(evaluated) / state.iterations();
  state.counters["in_scope"] = static_cast<double>(in_scope) / state.iterations();
}
BENCHMARK(BM_Synthetic)
    ->ArgNames({"cases", "index", "scaled"})
    ->Args({10000, 0, 0})
    ->Args({10000, 1, 0})
    ->Args({100000, 0, 0})
    ->Args({100000, 1, 0})
    ->Args({10000, 0, 1})
    ->Args({10000, 1, 1})
    ->Args({100000, 0, 1})
    ->Args({100000, 1, 1})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace foresight

BENCHMARK_MAIN();
