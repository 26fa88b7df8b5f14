// A retrieved case as the whole team reuses it (Ros et al. 2009, sec. 4.2): the case, the ball
// it was retrieved for (B^p), which robot plays which of its teammates (the correspondence the
// coordinator sends), every adapted position and target, and the ball path the gameplay plans
// (cbr/free_path.h). Every robot builds the same CasePlay from the coordinator's message.
#pragma once

#include "cbr/case.h"
#include "cbr/free_path.h"
#include "cbr/retrieval_params.h"
#include "cbr/team_messages.h"

namespace foresight {

struct CasePlay {
  int cycle = 0;
  int case_index = -1;
  const Case* c = nullptr;
  Vec2 p_F_ball{0.0, 0.0};  // B^p
  CaseRobots robots{-1, -1, -1, -1};  // case teammate i -> robot index
  std::array<Vec2, kMaxTeammates> adapted_F{Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  CaseBallPath path;
  int getter = -1;  // the case teammate whose first action is get_ball (sec. 2.2)

  int TeammateCount() const { return static_cast<int>(c->teammates.size()); }
  // The case teammate robot `robot` plays, or -1.
  int CaseTeammateOf(int robot) const;
  // A case point (position or target) moved with the ball: p - B^c + B^p (sec. 3.2, Fig. 5).
  Vec2 Adapt(const Vec2& case_p_F) const { return case_p_F - c->p_F_ball + p_F_ball; }
  // The robot index of the case teammate with case id `id`, or -1.
  int RobotOfId(int id) const;
  // The n-th trajectory (0-based) that case teammate `kicker` kicks, or nullptr.
  const FuzzyTrajectory* KickTrajectory(int kicker, int n) const;
};

CasePlay MakeCasePlay(const Case& c, int case_index, int cycle, const Vec2& p_F_ball,
                      const CaseRobots& robots, const RetrievalParams& params);

}  // namespace foresight
