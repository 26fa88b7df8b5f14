#include "cbr/ball_race.h"

#include <algorithm>
#include <limits>

namespace foresight {
double TimeToBall(const Vec2& p_F, const Vec2& ball_F, const RaceParams& params) {
  return std::max(0.0, (p_F - ball_F).norm() - params.reach_m) / params.speed_mps;
}

bool TeammateWins(const Problem& problem, int index, const BallRace& race,
                  const RaceParams& params) {
  const Vec2& p_F = problem.teammates[static_cast<std::size_t>(index)].pose.p_F;
  return TimeToBall(p_F, problem.p_F_ball, params) <= race.opponents_s + params.tie_s;
}

BallRace RunBallRace(const Problem& problem, const RaceParams& params) {
  BallRace race;
  race.team_s = std::numeric_limits<double>::infinity();
  race.opponents_s = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < problem.teammates.size(); ++i) {
    const double t = TimeToBall(problem.teammates[i].pose.p_F, problem.p_F_ball, params);
    if (t < race.team_s) {  // ties go to the lower index
      race.team_s = t;
      race.fastest = static_cast<int>(i);
    }
  }
  for (const Vec2& o : problem.opponents) {
    race.opponents_s = std::min(race.opponents_s, TimeToBall(o, problem.p_F_ball, params));
  }
  race.won = race.fastest >= 0 && race.team_s <= race.opponents_s + params.tie_s;
  return race;
}

}  // namespace foresight
