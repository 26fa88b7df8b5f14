// The strategies experiment (Mellmann & Schlotter, sec. V-B, Figs. 3 and 5): every strategy
// plays the ball from the same random start positions with the same seeds until goal or out
// (experiments/strategy_run.h), on the coarse model or, with a physics executor, in Bullet.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "common/shard.h"
#include "experiments/strategy_run.h"

namespace foresight {

struct StrategyRuns {
  Strategy strategy = Strategy::kFast;
  std::vector<StrategyRun> runs;  // one per start, in start order
  StrategyRun example;            // the run from params.example_start, with its steps
};

struct StrategiesResult {
  std::vector<StartPosition> starts;
  std::vector<StrategyRuns> strategies;  // in the params' order
};

// `executor` carries out the kicks: physics, or nullptr for the coarse simulator of the planner
// that decides. Runs (start, strategy) pairs in parallel; progress(done, total) counts runs.
// With a shard other than the whole run, only the shard's starts are played (every start is
// still drawn; the others' runs stay empty): experiments/strategies_shard.h merges the shards.
StrategiesResult RunStrategies(const StrategiesParams& params, const OutcomeSimulator* executor,
                               std::uint64_t seed, int threads,
                               const std::function<void(int, int)>& progress = {},
                               const Shard& shard = {});

// The starts and the empty runs of every strategy of a run of `params`.
StrategiesResult EmptyStrategiesResult(const StrategiesParams& params, std::uint64_t seed);

}  // namespace foresight
