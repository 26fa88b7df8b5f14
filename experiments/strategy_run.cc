#include "experiments/strategy_run.h"

#include <cmath>

#include "common/enum_names.h"
#include "common/random.h"
#include "planner/sampling.h"

namespace foresight {

namespace {

constexpr std::uint64_t kStartDomain = 0x7374617274706f73ULL;  // "startpos"
constexpr std::uint64_t kRunDomain = 0x73747261746e756eULL;
constexpr std::uint64_t kDecisionDomain = 1;
constexpr std::uint64_t kExecutionDomain = 2;

// Where the robot stands with heading theta so that the ball lies at its feet.
Vec2 SpotFor(const Vec2& p_F_ball, double theta_rad, const Vec2& p_R_ball) {
  Pose2 at_origin{Vec2(0.0, 0.0), theta_rad};
  return p_F_ball - at_origin.ToField(p_R_ball);
}

// Turns the robot towards the ball and walks it to the ball's feet; adds the times.
Pose2 Approach(const StrategiesParams& params, const Pose2& robot, const Vec2& p_F_ball,
               StrategyRun& run) {
  const Vec2 to_ball = p_F_ball - robot.p_F;
  double heading = robot.theta_rad;
  if (to_ball.norm() > 1e-9) heading = std::atan2(to_ball.y(), to_ball.x());
  run.turn_s += std::abs(WrapAngle(heading - robot.theta_rad)) / params.turn_speed_radps;
  const Vec2 spot = SpotFor(p_F_ball, heading, params.situation.state.p_R_ball);
  run.walk_s += (spot - robot.p_F).norm() / params.walk_speed_mps;
  return {spot, heading};
}

// The kick as executed: one draw of the kick's launch (coarse) or physics' own causes.
Outcome Execute(const StrategyRunContext& context, const Pose2& robot, const Vec2& p_F_ball,
                int kick, double rotation_rad, std::uint64_t key) {
  DrawnSample sample;
  sample.state = {robot, p_F_ball};
  RandomStream rng(key);
  sample.z_speed = rng.NextNormal();
  sample.z_direction = rng.NextNormal();
  sample.stream = key;
  const ConcreteAction action =
      MakeAction(context.params.situation.kicks, kick, rotation_rad, sample);
  return context.executor.Simulate(sample.state, action);
}

RunEnd EndOf(Category category) {
  switch (category) {
    case Category::kOppGoal:
      return RunEnd::kGoal;
    case Category::kOwnGoal:
      return RunEnd::kOwnGoal;
    default:
      return RunEnd::kOut;
  }
}

}  // namespace

std::string_view RunEndName(RunEnd end) {
  static constexpr EnumNames<RunEnd, 4> kNames{{{
      {RunEnd::kGoal, "goal"},
      {RunEnd::kOwnGoal, "own_goal"},
      {RunEnd::kOut, "out"},
      {RunEnd::kStepLimit, "step_limit"},
  }}};
  return kNames.Name(end);
}

StartPosition DrawStart(const FieldSpec& field, std::uint64_t seed, int start) {
  RandomStream rng(StreamKey(seed, static_cast<std::uint64_t>(start), kStartDomain));
  auto uniform = [&](double half) { return (2.0 * rng.NextUniform() - 1.0) * half; };
  // y before x in each point, one statement per draw: the order of a constructor's arguments is
  // unspecified, and y first is the order GCC gave the expressions these were before, so the
  // recorded starts keep their bytes and every compiler draws alike.
  StartPosition s;
  const double robot_y = uniform(field.HalfWidth());
  const double robot_x = uniform(field.HalfLength());
  s.robot.p_F = Vec2(robot_x, robot_y);
  s.robot.theta_rad = WrapAngle(uniform(kPi));
  const double ball_y = uniform(field.HalfWidth());
  const double ball_x = uniform(field.HalfLength());
  s.p_F_ball = Vec2(ball_x, ball_y);
  return s;
}

std::uint64_t RunKey(std::uint64_t seed, int start) {
  return StreamKey(seed, static_cast<std::uint64_t>(start), kRunDomain);
}

StrategyRun RunStrategy(const StrategyRunContext& context, Strategy strategy,
                        const StartPosition& start, std::uint64_t run_key, bool record_steps) {
  const StrategiesParams& params = context.params;
  StrategyRun run;
  Pose2 robot = start.robot;
  Vec2 ball = start.p_F_ball;
  StateEstimate belief = params.situation.state;
  for (int step = 0; step < params.max_steps; ++step) {
    robot = Approach(params, robot, ball, run);
    belief.robot = robot;
    const Decision d = context.planner.Decide(
        belief, strategy, params.situation.evaluation.samples,
        StreamKey(run_key, static_cast<std::uint64_t>(step), kDecisionDomain));
    ++run.steps;
    StrategyStep taken{robot, ball, d.kick_index, d.rotation_rad, {}};
    // Turning around the ball: the ball stays, the robot's heading changes by the rotation.
    run.around_ball_s += std::abs(d.rotation_rad) / params.turn_around_ball_speed_radps;
    const double heading = WrapAngle(robot.theta_rad + d.rotation_rad);
    if (d.kick_index != kNoKick) {
      taken.outcome =
          Execute(context, robot, ball, d.kick_index, d.rotation_rad,
                  StreamKey(run_key, static_cast<std::uint64_t>(step), kExecutionDomain));
      ++run.kicks;
      run.rotations_rad.push_back(d.rotation_rad);
      run.last_contact = taken.outcome.first_contact;
      run.kick_status.Add(CountStatuses({&taken.outcome, 1}));
    } else {
      taken.outcome.p_F_rest = ball;
    }
    robot = {SpotFor(ball, heading, params.situation.state.p_R_ball), heading};
    if (record_steps) run.steps_taken.push_back(taken);
    if (d.kick_index != kNoKick && taken.outcome.category != Category::kInfield) {
      run.end = EndOf(taken.outcome.category);
      return run;
    }
    ball = taken.outcome.p_F_rest;
  }
  run.end = RunEnd::kStepLimit;
  return run;
}

}  // namespace foresight
