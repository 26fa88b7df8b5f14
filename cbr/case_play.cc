#include "cbr/case_play.h"

#include "cbr/problem.h"

namespace foresight {

int CasePlay::CaseTeammateOf(int robot) const {
  for (int i = 0; i < TeammateCount(); ++i) {
    if (robots[static_cast<std::size_t>(i)] == robot) return i;
  }
  return -1;
}

int CasePlay::RobotOfId(int id) const {
  for (int i = 0; i < TeammateCount(); ++i) {
    if (c->teammates[static_cast<std::size_t>(i)].id == id) {
      return robots[static_cast<std::size_t>(i)];
    }
  }
  return -1;
}

const FuzzyTrajectory* CasePlay::KickTrajectory(int kicker, int n) const {
  for (const FuzzyTrajectory& t : path.View()) {
    if (t.kicker != kicker) continue;
    if (n-- == 0) return &t;
  }
  return nullptr;
}

CasePlay MakeCasePlay(const Case& c, int case_index, int cycle, const Vec2& p_F_ball,
                      const CaseRobots& robots, const RetrievalParams& params) {
  CasePlay play;
  play.cycle = cycle;
  play.case_index = case_index;
  play.c = &c;
  play.p_F_ball = p_F_ball;
  play.robots = robots;
  for (int i = 0; i < play.TeammateCount(); ++i) {
    play.adapted_F[static_cast<std::size_t>(i)] = play.Adapt(c.teammates[static_cast<std::size_t>(i)].p_F);
  }
  play.getter = BallGetter(c);
  Problem problem;
  problem.p_F_ball = p_F_ball;
  problem.defending = c.defending;
  play.path = BuildBallPath(problem, c,
                            std::span<const Vec2>(play.adapted_F.data(),
                                                  static_cast<std::size_t>(play.TeammateCount())),
                            params);
  return play;
}

}  // namespace foresight
