// The ball path of a case's gameplay and the free-path test (Ros et al. 2009, sec. 3.3.1,
// Fig. 7, 8a).
//
// A fuzzy trajectory from s along the unit vector u with length l has, at a point p with
// x' = (p - s).u (along) and y' = (p - s).n (across, n = u turned +90 degrees),
//   mu(p)  = exp(-(y' / rho(x'))^2)  for 0 <= x' <= l,  0 elsewhere      (sec. 3.3.1)
//   rho(x') = r_min + (r_max - r_min) x' / l                              (linear, Fig. 7a)
// so mu = exp(-1) = thr_t exactly on the trapezoid with half-widths r_min and r_max (Fig. 7a).
// Decision (the paper is silent): behind the start (x' < 0) and past the end (x' > l) mu = 0.
// Behind the start stands the kicker, which shields the ball; past the end the ball has stopped
// (at the receiver for a pass), so an opponent there does not block this trajectory (the next
// trajectory, if any, starts there and covers it). A trajectory of length 0 covers nothing.
//
// Widths from the kick model (RetrievalParams::widths = kick_model). The kick's direction is
// alpha ~ N(alpha_0, sigma_alpha^2) (models/kick_model.h). At distance x along the nominal line
// the ball's centre is off the line by x tan(alpha - alpha_0); within k standard deviations
// (k = width_sigmas) that is at most x tan(k sigma_alpha). An opponent (a disc of radius R =
// opponent_radius_m) meets the ball (radius r_b = ball_radius_m) when their centres are closer
// than R + r_b, so the opponents that can stop the ball have |y'| <= R + r_b + x tan(k
// sigma_alpha). Putting mu's exp(-1) edge there gives
//   rho(x') = R + r_b + x' tan(k sigma_alpha):  r_min = R + r_b,  r_max = R + r_b + l tan(k sigma)
// which is linear in x' like the paper's rho; with k = 1 the ball stays inside for 68 % of kicks.
//
// The gameplay order: the walk starts with the first teammate (case order) whose first action is
// get_ball, with the ball at the problem's ball, and follows that robot's actions:
//   pass:  a trajectory to the receiver's adapted position (or, if the receiver goes to a target
//          before its receive action, to that target, adapted); the walk continues with the
//          receiver after its receive action;
//   kick:  at goal: to the centre of the attacked goal (AttackSign(defending) * goal_x_m, 0);
//          to a target: to the target adapted like a position (target - B^c + B^p); a kick into
//          the field (not a shot, cbr/case.h IsShot) whose mean roll (roll_m > 0) lies beyond
//          its target runs on to it past a knee at the target (MakeKickTrajectory): a kick
//          of fixed strength rolls as far as it rolls, whatever the target. The mean roll is
//          where the ball is expected to stop, as the paper's trajectory is the ball's expected
//          path; run on to the reach at 2 sd, the corridor put a goalie 3.7 m away on a 2 m kick
//          up the wing, which then never played where it was written for. The walk goes on from
//          the target, where the case plans the ball; the robot aims at the target. Decision:
//          targets are part of the case's pattern around the ball, so they move with it exactly as
//          the teammates do (Fig. 5); a fixed field point would turn a pass-to-space into a kick
//          to somewhere unrelated when the ball is elsewhere in its scope;
//   dribble to a target: moves the ball there (adapted) without a trajectory (no kick);
//   others: no ball movement.
// A kick's entry with reach_m > 0 cuts its trajectory to that length; the ball then continues
// from where the trajectory ends. Passes end at their receiver, whose body stops the ball.
#pragma once

#include <array>
#include <span>

#include "cbr/case.h"
#include "cbr/correspondence.h"
#include "cbr/problem.h"
#include "cbr/retrieval_params.h"
#include "common/geometry.h"

namespace foresight {

inline constexpr int kMaxTrajectories = 8;

struct FuzzyTrajectory {
  Vec2 start_F{0.0, 0.0};
  Vec2 end_F{0.0, 0.0};
  Vec2 u{1.0, 0.0};  // unit direction (start -> end); (1, 0) when length is 0
  double length_m = 0.0;
  double r_start_m = 0.0;                 // rho(0)
  double r_end_m = 0.0;                   // rho(l), or rho(knee_m) and beyond
  // > 0: rho grows from r_start_m to r_end_m over the planned knee_m (the case's target) and
  // stays at r_end_m to length_m (the kick's reach; MakeKickTrajectory).
  double knee_m = 0.0;
  Vec2 aim_F{0.0, 0.0};  // where the kick is aimed: end_F, or the target before the knee
  ActionType action = ActionType::kKick;  // kKick or kPass
  int kicker = -1;                        // case teammate index
  int receiver = -1;                      // case teammate index for a pass
  const CaseAction* kick = nullptr;       // the kick or pass action (points into the case)
};

// mu of sec. 3.3.1 at p_F, and its exponent (y'/rho)^2 (+infinity where mu = 0); with a knee,
// rho(x') = r_start + (r_end - r_start) min(x' / knee, 1).
double TrajectoryExponent(const FuzzyTrajectory& t, const Vec2& p_F);
double TrajectoryMembership(const FuzzyTrajectory& t, const Vec2& p_F);

// A trajectory from start to end (cut to reach_m when > 0) with widths of `kick` per `params`.
FuzzyTrajectory MakeTrajectory(const Vec2& start_F, const Vec2& end_F, const KickTrajectory& kick,
                               const RetrievalParams& params);
// A kick into the field, aimed at target_F: MakeTrajectory's, and when the kick's mean roll lies
// beyond the target, run on to it with the knee at the target (the widths of the planned part
// stay those of a trajectory to the target; past it rho stays r_end_m).
FuzzyTrajectory MakeKickTrajectory(const Vec2& start_F, const Vec2& target_F,
                                   const KickTrajectory& kick, const RetrievalParams& params);

struct CaseBallPath {
  std::array<FuzzyTrajectory, kMaxTrajectories> trajectories{};
  int count = 0;
  bool overflow = false;  // the gameplay kicks more than kMaxTrajectories times (rest dropped)
  std::span<const FuzzyTrajectory> View() const {
    return {trajectories.data(), static_cast<std::size_t>(count)};
  }
};

// The ball path of case `c` played from problem `problem`'s ball, with the case's teammates at
// `adapted_F` (indexed like c.teammates).
CaseBallPath BuildBallPath(const Problem& problem, const Case& c, std::span<const Vec2> adapted_F,
                           const RetrievalParams& params);

// free_path(p, c) = 1 - max_t phi_t(Opp) (sec. 3.3.1), with the first blocker when not free.
struct PathCheck {
  bool free = true;
  int opponent = -1;    // index into Problem::opponents
  int trajectory = -1;  // index into CaseBallPath
  double membership = 0.0;
};
PathCheck CheckFreePath(const CaseBallPath& path, std::span<const Vec2> opponents_F, double thr_t);

}  // namespace foresight
