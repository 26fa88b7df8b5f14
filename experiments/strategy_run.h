// One run of the strategies experiment (Mellmann & Schlotter, sec. V-B): from a start position
// the robot plays the ball on an empty field until it is in a goal or out, or a step limit.
//
// A step: the robot turns on the spot towards the ball (turn_speed), walks straight until the
// ball lies at its feet (walk_speed; the situation's ball offset), decides with its strategy on
// its belief (the true pose with the situation's sigmas), turns around the ball by the chosen
// rotation (turn_around_ball_speed), and kicks. The kick is executed by an OutcomeSimulator from
// the true state: the coarse simulator with one drawn launch of the chosen kick (the paper:
// "the ball position after the kick is determined by drawing one sample"), or physics, which
// ignores the drawn launch and kicks with the robot's motion. After the kick the robot stands
// where it kicked from.
//
// Randomness: the start from StreamKey(seed, start, start domain); step k's decision seed and
// execution draws from the run key StreamKey(seed, start, run domain), the same for every
// strategy (common random numbers between strategies).
#pragma once

#include <cstdint>
#include <vector>

#include "experiments/experiment_params.h"
#include "models/outcome.h"
#include "planner/coarse_planner.h"

namespace foresight {

struct StartPosition {
  Pose2 robot;
  Vec2 p_F_ball{0.0, 0.0};
};

// Robot and ball uniform over the field between its lines, the robot's heading uniform.
StartPosition DrawStart(const FieldSpec& field, std::uint64_t seed, int start);

enum class RunEnd : std::uint8_t { kGoal, kOwnGoal, kOut, kStepLimit };
std::string_view RunEndName(RunEnd end);

struct StrategyStep {
  Pose2 robot_at_ball;      // before the turn around the ball
  Vec2 p_F_ball{0.0, 0.0};  // where the ball was kicked from
  int kick_index = -1;      // -1: the strategy kicked nothing this step
  double rotation_rad = 0.0;
  Outcome outcome;
};

struct StrategyRun {
  RunEnd end = RunEnd::kStepLimit;
  int kicks = 0;        // kicks made (steps with a kick)
  int steps = 0;        // decisions made
  double turn_s = 0.0;  // turning on the spot towards the ball
  double walk_s = 0.0;
  double around_ball_s = 0.0;             // turning around the ball before kicks
  Contact last_contact = Contact::kNone;  // the last kick's first contact
  StatusCounts kick_status;           // kicks the executor missed or that did not settle (physics)
  std::vector<double> rotations_rad;  // the turn around the ball of every kick, signed
  std::vector<StrategyStep> steps_taken;  // only when recorded

  double TotalTime() const { return turn_s + walk_s + around_ball_s; }
};

struct StrategyRunContext {
  const StrategiesParams& params;
  const CoarsePlanner& planner;      // decisions (coarse model, the situation's belief)
  const OutcomeSimulator& executor;  // what really happens to a kicked ball
};

StrategyRun RunStrategy(const StrategyRunContext& context, Strategy strategy,
                        const StartPosition& start, std::uint64_t run_key, bool record_steps);

// The run key of start `start` (shared by all strategies).
std::uint64_t RunKey(std::uint64_t seed, int start);

}  // namespace foresight
