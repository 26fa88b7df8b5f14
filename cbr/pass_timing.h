// A timing-aware pass check (beyond the paper). The free-path test of sec. 3.3.1 asks
// only whether an opponent stands inside a pass's fuzzy corridor now; it ignores time: an
// opponent just outside the corridor but fast enough to step in passes the test, a slow one far
// down a long corridor fails it. This check forward-simulates each pass of a case's ball path
// the way the first paper simulates kicks (Mellmann & Schlotter, sec. III: samples of the
// kick's noise, the coarse rolling model of planner/ball_roll.h) and asks, per sample, whether
// an opponent can reach the ball before the receiver has it:
//   kick:      v ~ N(v0, sigma_v^2), heading ~ N(aim, sigma_alpha^2) from the kick model, with
//              aim the pass's direction (the passer aims the kick's mean direction at it);
//   ball:      s(t) = v t - a t^2 / 2 along the heading, at rest after v^2 / 2a;
//   receiver:  has the ball when it arrives within reach of the pass's end, or, if the ball
//              stops short, when the receiver (starting when the pass is kicked) has walked to it;
//   opponent:  can be at p by T(p) = reaction_s + max(0, |p - o| - reach_m) / speed_mps, and
//              intercepts if T(ball(t)) <= t at some t before the receiver has the ball
//              (checked every time_step_s).
// reach_m is an opponent's body radius plus the ball's radius (it stops the ball on contact, as
// in the match simulator). The estimate is the share of samples no opponent intercepts, the
// product over the case's passes. Samples are fixed standard-normal pairs (common random
// numbers: every case is judged on the same draws, and retrieval stays deterministic).
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "cbr/free_path.h"
#include "models/kick_model.h"

namespace foresight {

struct PassTimingParams {
  bool enabled = false;
  double reaction_s = 0.0;        // an opponent's reaction time before it walks
  double opponent_speed_mps = 0.0;  // its walking speed (the match's robot file)
  double receiver_speed_mps = 0.0;  // the receiver's (the same robots)
  double reach_m = 0.0;           // body radius + ball radius
  double time_step_s = 0.0;
  double min_success = 0.0;       // a case whose estimate is lower is not retrieved
  std::vector<std::pair<double, double>> z;  // standard normals (speed, direction) per sample
};

// Draws `samples` fixed standard-normal pairs into params->z.
void DrawPassSamples(int samples, PassTimingParams* params);

// The estimated probability that every pass of `path` reaches its receiver before an opponent
// at `opponents_F` can get to the ball; 1 for a path without passes.
double PassSuccess(const CaseBallPath& path, std::span<const Vec2> opponents_F,
                   const KickModel& kicks, const PassTimingParams& params);

}  // namespace foresight
