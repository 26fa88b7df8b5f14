#include "experiments/strategies_shard.h"

#include "common/geometry.h"

namespace foresight {

namespace {

// No part of a run takes a day (assumption: runs end after max_steps decisions of seconds each).
constexpr double kMaxRunTime_s = 86400.0;

nlohmann::json StepJson(const StrategyStep& step) {
  return {ExactJson(step.robot_at_ball.p_F.x()), ExactJson(step.robot_at_ball.p_F.y()),
          ExactJson(step.robot_at_ball.theta_rad), ExactJson(step.p_F_ball.x()),
          ExactJson(step.p_F_ball.y()), step.kick_index, ExactJson(step.rotation_rad),
          OutcomeShardJson(step.outcome)};
}

StrategyStep ReadStep(const ShardValue& v, int kicks) {
  if (v.Size() != 8) v.Fail("must be [robot x, y, theta, ball x, y, kick, rotation, outcome]");
  StrategyStep step;
  step.robot_at_ball = {{v.At(0).Finite(), v.At(1).Finite()}, v.At(2).InRange(-2.0 * kPi, 2.0 * kPi)};
  step.p_F_ball = {v.At(3).Finite(), v.At(4).Finite()};
  step.kick_index = v.At(5).IntInRange(kNoKick, kicks - 1);
  step.rotation_rad = v.At(6).InRange(-2.0 * kPi, 2.0 * kPi);
  step.outcome = ReadShardOutcome(v.At(7));
  return step;
}

nlohmann::json RunJson(const StrategyRun& run) {
  nlohmann::json rotations = nlohmann::json::array(), steps = nlohmann::json::array();
  for (double r : run.rotations_rad) rotations.push_back(ExactJson(r));
  for (const StrategyStep& step : run.steps_taken) steps.push_back(StepJson(step));
  nlohmann::json j = {static_cast<int>(run.end),
                      run.kicks,
                      run.steps,
                      ExactJson(run.turn_s),
                      ExactJson(run.walk_s),
                      ExactJson(run.around_ball_s),
                      static_cast<int>(run.last_contact),
                      run.kick_status.missed,
                      run.kick_status.not_settled,
                      rotations,
                      run.kick_status.fell,
                      run.kick_status.blocked};
  if (!steps.empty()) j.push_back(steps);
  return j;
}

template <typename Enum>
Enum ReadEnum(const ShardValue& v, Enum last) {
  const int n = v.Int();
  if (n < 0 || n > static_cast<int>(last)) v.Fail("must be 0 .. " + std::to_string(static_cast<int>(last)));
  return static_cast<Enum>(n);
}

// A run as RunStrategy makes it (experiments/strategy_run.h): at most max_steps decisions, a
// kick in some of them and one turn around the ball per kick, times that are not negative.
StrategyRun ReadRun(const ShardValue& v, const StrategiesParams& params) {
  const int kicks = static_cast<int>(params.situation.kicks.kicks.size());
  if (v.Size() != 12 && v.Size() != 13) v.Fail("must be a run of 12 or 13 entries");
  StrategyRun run;
  run.end = ReadEnum(v.At(0), RunEnd::kStepLimit);
  run.steps = v.At(2).IntInRange(0, params.max_steps);
  run.kicks = v.At(1).IntInRange(0, run.steps);
  run.turn_s = v.At(3).InRange(0.0, kMaxRunTime_s);
  run.walk_s = v.At(4).InRange(0.0, kMaxRunTime_s);
  run.around_ball_s = v.At(5).InRange(0.0, kMaxRunTime_s);
  run.last_contact = ReadEnum(v.At(6), Contact::kRobot);
  run.kick_status = {v.At(7).IntInRange(0, run.kicks), v.At(8).IntInRange(0, run.kicks),
                     v.At(10).IntInRange(0, run.kicks), v.At(11).IntInRange(0, run.kicks)};
  const ShardValue rotations = v.At(9);
  if (rotations.Size() != static_cast<std::size_t>(run.kicks))
    rotations.Fail("must have one turn per kick (" + std::to_string(run.kicks) + ")");
  for (std::size_t i = 0; i < rotations.Size(); ++i)
    run.rotations_rad.push_back(rotations.At(i).InRange(-2.0 * kPi, 2.0 * kPi));
  if (v.Size() == 13) {
    const ShardValue steps = v.At(12);
    for (std::size_t i = 0; i < steps.Size(); ++i)
      run.steps_taken.push_back(ReadStep(steps.At(i), kicks));
  }
  return run;
}

}  // namespace

nlohmann::json StrategiesShardResults(const StrategiesParams& params,
                                      const StrategiesResult& result, const Shard& shard) {
  nlohmann::json items = nlohmann::json::array();
  for (int k = 0; k < shard.OwnedCount(params.starts); ++k) {
    const int start = shard.Item(k);
    nlohmann::json runs = nlohmann::json::array();
    for (const StrategyRuns& s : result.strategies) runs.push_back(RunJson(s.runs[start]));
    nlohmann::json item = {{"start", start}, {"runs", runs}};
    if (start == params.example_start) {
      nlohmann::json examples = nlohmann::json::array();
      for (const StrategyRuns& s : result.strategies) examples.push_back(RunJson(s.example));
      item["example"] = examples;
    }
    items.push_back(item);
  }
  return items;
}

StrategiesResult MergeStrategiesShards(const StrategiesParams& params, std::uint64_t seed,
                                       const std::vector<ShardPart>& parts) {
  StrategiesResult result = EmptyStrategiesResult(params, seed);
  const std::size_t strategies = result.strategies.size();
  for (const ShardPart& part : parts) {
    const Shard& shard = part.header.shard;
    const ShardValue items = ResultsOf(part);
    for (int k = 0; k < shard.OwnedCount(params.starts); ++k) {
      const ShardValue item = items.At(k);
      const int start = shard.Item(k);
      if (item["start"].Int() != start) item["start"].Fail("must be " + std::to_string(start));
      const ShardValue runs = item["runs"];
      if (runs.Size() != strategies) runs.Fail("must have one run per strategy");
      for (std::size_t s = 0; s < strategies; ++s)
        result.strategies[s].runs[start] = ReadRun(runs.At(s), params);
      if (start != params.example_start) continue;
      const ShardValue examples = item["example"];
      if (examples.Size() != strategies) examples.Fail("must have one run per strategy");
      for (std::size_t s = 0; s < strategies; ++s)
        result.strategies[s].example = ReadRun(examples.At(s), params);
    }
  }
  return result;
}

}  // namespace foresight
