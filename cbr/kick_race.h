// The race for the kick: whether the robot that gets the ball in a case plays it away (its first
// kick or pass) before an opponent reaches the ball. The ball race (cbr/ball_race.h) asks only
// who reaches the ball first; but a case then holds the ball while its getter grabs it, dribbles,
// turns with it and aims, and the team gives the case up as soon as an opponent touches the ball
// (ball_lost, cbr/case_actions.h). Ros et al. 2009 name this failure (sec. 5.3.1: "the defender
// may reach the ball first") and give the robots no measure of it; the model below is ours.
//
// The getter (problem teammate at p, heading theta, adapted position A) and the ball B, every
// time from the match's robot (models/match/<robot>.json) and the rules; the getter walks to A
// (next to the ball, sec. 4.2), then to the ball, as the team plays it:
//   t_get    = |A - p| / speed_mps + TimeToBall(A, B)               (cbr/ball_race.h)
//   heading  = the direction A -> B (theta when A is on the ball)
//   t_hold   = for each action before its first kick or pass, in case order:
//                turn:    |turn| / dribble_turn_radps
//                dribble: |turn to the target| / dribble_turn_radps + |d| / dribble_speed_mps
//                         (target adapted like the case's positions, cbr/case_play.h)
//                a walk, wait or receive before the kick: not judged
//            + the aim: |turn to (trajectory end - kick direction)| / dribble_turn_radps
//   t_hold runs from the grab's end, as the ball-holding rule's clock does, and is capped at
//   hold_limit_s (the rule kicks the ball away then, aimed or not); the ball leaves launch_s
//   after the kick starts:
//   t_kick   = t_get + grab_s + min(t_hold, hold_limit_s) + launch_s.
// An opponent at o ends the case when it reaches any point of the ball's held path H (from B
// through the dribble targets to the kick spot), t_o = max(0, dist(o, H) - reach_m) / speed_mps:
// where along H the ball is when the opponent gets there is left out, so the test is on the
// safe side of a robot that meets the ball anywhere it will be. The getter wins when
//   t_kick <= min_o t_o.
// No tie rule (unlike the ball race): a touch at the moment of the kick already ends the case.
// The turns take the short way, as the case actions do; the walk to the ball is straight.
#pragma once

#include "cbr/ball_race.h"
#include "cbr/case.h"
#include "cbr/correspondence.h"
#include "cbr/free_path.h"
#include "cbr/problem.h"
#include "models/kick_model.h"

namespace foresight {

struct HoldParams {
  double grab_s = 0.0;             // grabbing the ball
  double dribble_speed_mps = 0.0;  // walking with it
  double dribble_turn_radps = 0.0; // turning with it
  double hold_limit_s = 0.0;       // the holding rule starts the kick after holding this long
  double launch_s = 0.0;           // from the kick's start until the ball leaves
};

// How long a robot holds the ball before the kick of `kick_trajectory` starts: actions
// [from_action, the kick) of case teammate `teammate` (turn, dribble; anything else: not judged),
// from heading_rad with the ball at ball_F, case points moved by shift_F (B^p - B^c). The ball's
// held path runs from ball_F through the dribble targets to the kick spot.
struct HoldPlan {
  double hold_s = 0.0;      // uncapped
  double turns_rad = 0.0;   // summed turns with the ball, the aim included
  double dribble_m = 0.0;   // summed dribbles
  std::array<Vec2, kMaxTrajectories + 2> held{};
  std::size_t points = 0;
  bool judged = false;
};
HoldPlan PlanHold(const Case& c, int teammate, std::size_t from_action,
                  const FuzzyTrajectory& kick_trajectory, double heading_rad, const Vec2& ball_F,
                  const Vec2& shift_F, const KickModel& kicks, const HoldParams& hold);

struct KickRace {
  double kick_s = 0.0;       // t_kick, from now
  double hold_s = 0.0;       // min(t_hold, hold_limit_s)
  double opponents_s = 0.0;  // the first opponent's time to the held path (+infinity: none)
  Vec2 kick_spot_F{0.0, 0.0};
  bool judged = false;       // the getter has a kick or pass to race for
  bool won = true;
};

// The race of case teammate `getter` (BallGetter(c)) under `match`, whose ball path is `path`
// (BuildBallPath with match's adapted positions). Not judged (won) when the getter's part has no
// kick or pass, or a receive or wait comes before it.
KickRace RunKickRace(const Problem& problem, const Case& c, const Correspondence& match,
                     int getter, const CaseBallPath& path, const KickModel& kicks,
                     const RaceParams& race, const HoldParams& hold);

}  // namespace foresight
