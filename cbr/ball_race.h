// The race for the ball: which robot reaches the ball first, from the problem's positions and the
// robots' speeds. Ros et al. 2009 send the robot closest to the ball for it (sec. 4.1: the
// coordinator is the robot closest to the ball; sec. 5.3.1: "since robot A is closer to the
// ball, it is in charge of reusing alone the second case"), and a case fails "while the robot is
// moving towards the ball, the defender may reach the ball first" (sec. 5.3.1). The model:
// every robot walks straight at speed_mps until its body touches the ball,
//   t_i = max(0, |p_i - B| - reach_m) / speed_mps,     reach_m = body radius + ball radius,
// and a robot wins when no opponent beats it by more than tie_s (t <= min_opponents t + tie_s);
// the team wins when its fastest robot does.
// tie_s is one control step: robots that arrive within one step of each other arrive together
// as far as any robot can act on it. Decision: a tie goes to the team, whose robot is already on
// its way (no case is needed to get the ball). Turning towards the ball is left out for both
// sides (problems carry no opponent headings).
#pragma once

#include "cbr/problem.h"

namespace foresight {

struct RaceParams {
  double speed_mps = 0.0;  // every robot's walking speed (the match's robot file)
  double reach_m = 0.0;    // body radius + ball radius
  double tie_s = 0.0;
};

struct BallRace {
  int fastest = -1;             // problem teammate index, -1 without teammates
  double team_s = 0.0;          // its time to the ball
  double opponents_s = 0.0;     // the fastest opponent's (+infinity without opponents)
  bool won = false;
};

BallRace RunBallRace(const Problem& problem, const RaceParams& params);

// t of a robot at p_F (the formula above).
double TimeToBall(const Vec2& p_F, const Vec2& ball_F, const RaceParams& params);

// Whether problem teammate `index` reaches the ball no later than race.opponents_s + tie_s.
bool TeammateWins(const Problem& problem, int index, const BallRace& race,
                  const RaceParams& params);

}  // namespace foresight
