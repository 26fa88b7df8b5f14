#include "cbr/free_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace foresight {
namespace {

int TeammateIndex(const Case& c, int id) {
  for (std::size_t i = 0; i < c.teammates.size(); ++i) {
    if (c.teammates[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

double TrajectoryExponent(const FuzzyTrajectory& t, const Vec2& p_F) {
  constexpr double kOutside = std::numeric_limits<double>::infinity();
  if (!(t.length_m > 0.0)) return kOutside;
  const Vec2 d = p_F - t.start_F;
  const double along = d.dot(t.u);
  if (along < 0.0 || along > t.length_m) return kOutside;
  const double across = t.u.x() * d.y() - t.u.y() * d.x();  // d . (-u_y, u_x)
  const double planned = t.knee_m > 0.0 ? t.knee_m : t.length_m;
  const double rho = t.r_start_m + (t.r_end_m - t.r_start_m) * std::min(along / planned, 1.0);
  const double q = across / rho;
  return q * q;
}

double TrajectoryMembership(const FuzzyTrajectory& t, const Vec2& p_F) {
  return std::exp(-TrajectoryExponent(t, p_F));
}

FuzzyTrajectory MakeTrajectory(const Vec2& start_F, const Vec2& end_F, const KickTrajectory& kick,
                               const RetrievalParams& params) {
  FuzzyTrajectory t;
  t.start_F = start_F;
  const Vec2 d = end_F - start_F;
  double length = d.norm();
  if (length > 0.0) t.u = d / length;
  if (kick.reach_m > 0.0 && length > kick.reach_m) length = kick.reach_m;
  t.length_m = length;
  t.end_F = start_F + t.u * length;
  t.aim_F = t.end_F;
  if (params.widths == TrajectoryWidths::kKickModel && kick.sigma_direction_rad > 0.0) {
    t.r_start_m = params.opponent_radius_m + params.ball_radius_m;
    t.r_end_m = t.r_start_m + length * std::tan(params.width_sigmas * kick.sigma_direction_rad);
  } else {
    t.r_start_m = kick.r_min_m;
    t.r_end_m = kick.r_max_m;
  }
  return t;
}

FuzzyTrajectory MakeKickTrajectory(const Vec2& start_F, const Vec2& target_F,
                                   const KickTrajectory& kick, const RetrievalParams& params) {
  FuzzyTrajectory t = MakeTrajectory(start_F, target_F, kick, params);
  if (kick.roll_m > t.length_m && t.length_m > 0.0) {
    t.knee_m = t.length_m;
    t.length_m = kick.roll_m;
    t.end_F = start_F + t.u * t.length_m;
  }
  return t;
}

CaseBallPath BuildBallPath(const Problem& problem, const Case& c, std::span<const Vec2> adapted_F,
                           const RetrievalParams& params) {
  CaseBallPath path;
  const int m = static_cast<int>(c.teammates.size());
  int robot = BallGetter(c);
  if (robot < 0) return path;
  std::array<std::size_t, kMaxTeammates> cursor{};
  Vec2 ball = problem.p_F_ball;
  const Vec2 shift = problem.p_F_ball - c.p_F_ball;
  const auto add = [&](const Vec2& end, const CaseAction& a, int receiver) {
    const KickTrajectory& k = params.TrajectoryFor(a.kick);
    const bool into_field = a.type == ActionType::kKick && !IsShot(a, params.goal_x_m);
    FuzzyTrajectory t = into_field ? MakeKickTrajectory(ball, end, k, params)
                                   : MakeTrajectory(ball, end, k, params);
    t.action = a.type;
    t.kicker = robot;
    t.receiver = receiver;
    t.kick = &a;
    ball = t.aim_F;  // the gameplay goes on from where the case plans the ball
    if (path.count == kMaxTrajectories) {
      path.overflow = true;
    } else {
      path.trajectories[path.count++] = t;
    }
  };
  while (robot >= 0 && robot < m && cursor[robot] < c.teammates[robot].actions.size()) {
    const CaseAction& a = c.teammates[robot].actions[cursor[robot]++];
    switch (a.type) {
      case ActionType::kKick:
        if (a.at_goal) {
          add(Vec2(AttackSign(c.defending) * params.goal_x_m, 0.0), a, -1);
        } else if (a.target_F) {
          add(*a.target_F + shift, a, -1);
        }
        break;
      case ActionType::kPass: {
        const int r = TeammateIndex(c, a.teammate);
        if (r < 0 || r == robot) break;
        Vec2 at = adapted_F[r];
        const auto& ra = c.teammates[r].actions;
        std::size_t k = cursor[r];
        for (; k < ra.size() && ra[k].type != ActionType::kReceive; ++k) {
          if (ra[k].type == ActionType::kGoTo && ra[k].target_F) at = *ra[k].target_F + shift;
        }
        add(at, a, r);
        if (k == ra.size()) return path;  // the receiver never receives: the walk ends
        cursor[r] = k + 1;
        robot = r;
        break;
      }
      case ActionType::kDribble:
        if (a.target_F) ball = *a.target_F + shift;
        break;
      default:
        break;
    }
  }
  return path;
}

PathCheck CheckFreePath(const CaseBallPath& path, std::span<const Vec2> opponents_F, double thr_t) {
  PathCheck check;
  const double limit = -std::log(thr_t);  // mu > thr_t <=> (y'/rho)^2 < -ln thr_t: no exp
  for (int t = 0; t < path.count; ++t) {
    for (std::size_t o = 0; o < opponents_F.size(); ++o) {
      const double q2 = TrajectoryExponent(path.trajectories[t], opponents_F[o]);
      if (q2 < limit) {
        check.free = false;
        check.opponent = static_cast<int>(o);
        check.trajectory = t;
        check.membership = std::exp(-q2);
        return check;
      }
    }
  }
  return check;
}

}  // namespace foresight
