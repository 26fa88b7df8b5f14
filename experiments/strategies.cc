#include "experiments/strategies.h"

#include "common/parallel_for.h"

namespace foresight {

StrategiesResult EmptyStrategiesResult(const StrategiesParams& params, std::uint64_t seed) {
  StrategiesResult result;
  for (int i = 0; i < params.starts; ++i) {
    result.starts.push_back(DrawStart(params.situation.field, seed, i));
  }
  result.strategies.resize(params.strategies.size());
  for (std::size_t s = 0; s < params.strategies.size(); ++s) {
    result.strategies[s].strategy = params.strategies[s];
    result.strategies[s].runs.resize(static_cast<std::size_t>(params.starts));
  }
  return result;
}

StrategiesResult RunStrategies(const StrategiesParams& params, const OutcomeSimulator* executor,
                               std::uint64_t seed, int threads,
                               const std::function<void(int, int)>& progress,
                               const Shard& shard) {
  StrategiesResult result = EmptyStrategiesResult(params, seed);
  const CoarsePlanner planner(params.situation);
  const StrategyRunContext context{params, planner,
                                   executor != nullptr ? *executor : planner.simulator()};
  const int strategies = static_cast<int>(params.strategies.size());
  // Start-major order, so that a partial run (and its progress) covers every strategy alike.
  ParallelFor(
      shard.OwnedCount(params.starts) * strategies, threads,
      [&](int job) {
        const int start = shard.Item(job / strategies), s = job % strategies;
        StrategyRuns& target = result.strategies[static_cast<std::size_t>(s)];
        const bool example = start == params.example_start;
        StrategyRun run = RunStrategy(context, target.strategy, result.starts[start],
                                      RunKey(seed, start), example);
        if (example) target.example = run;
        run.steps_taken.clear();
        target.runs[static_cast<std::size_t>(start)] = std::move(run);
      },
      progress);
  return result;
}

}  // namespace foresight
