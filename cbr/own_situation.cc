#include "cbr/own_situation.h"

#include <vector>

namespace foresight {

Problem CaseOwnProblem(const Case& c) {
  Problem p;
  p.p_F_ball = c.p_F_ball;
  p.defending = c.defending;
  const double heading = AttackSign(c.defending) > 0 ? 0.0 : kPi;
  for (const CaseTeammate& t : c.teammates) p.teammates.push_back({t.id, Pose2{t.p_F, heading}});
  for (const CaseOpponent& o : c.opponents) p.opponents.push_back(o.p_F);
  return p;
}

CaseBallPath OwnBallPath(const Case& c, const RetrievalParams& params) {
  std::vector<Vec2> own;
  for (const CaseTeammate& t : c.teammates) own.push_back(t.p_F);
  return BuildBallPath(CaseOwnProblem(c), c, own, params);
}

PathCheck OwnPathCheck(const Case& c, const RetrievalParams& params) {
  std::vector<Vec2> opponents;
  for (const CaseOpponent& o : c.opponents) opponents.push_back(o.p_F);
  return CheckFreePath(OwnBallPath(c, params), opponents, params.thr_trajectory);
}

}  // namespace foresight
