#include "cbr/case_holding.h"

#include <cmath>
#include <cstdio>

#include "cbr/free_path.h"
#include "cbr/problem.h"
#include "common/geometry.h"
#include "models/walk_command.h"

namespace foresight {

namespace {

// Index of the action `a` points to in teammate t's actions, or the size when absent.
std::size_t IndexOf(const Case& c, int t, const CaseAction* a) {
  const auto& actions = c.teammates[static_cast<std::size_t>(t)].actions;
  for (std::size_t i = 0; i < actions.size(); ++i) {
    if (&actions[i] == a) return i;
  }
  return actions.size();
}

// The action after the last get_ball or receive before `end` (where holding the ball starts).
std::size_t HoldStart(const Case& c, int t, std::size_t end) {
  const auto& actions = c.teammates[static_cast<std::size_t>(t)].actions;
  for (std::size_t i = end; i-- > 0;) {
    if (actions[i].type == ActionType::kGetBall || actions[i].type == ActionType::kReceive) {
      return i + 1;
    }
  }
  return 0;
}

}  // namespace

std::vector<HoldingFinding> CheckCaseHolding(const Case& c, const KickModel& kicks,
                                             const RetrievalParams& params, const HoldParams& hold) {
  Problem own;
  own.p_F_ball = c.p_F_ball;
  own.defending = c.defending;
  std::vector<Vec2> positions;
  for (const CaseTeammate& t : c.teammates) positions.push_back(t.p_F);
  const CaseBallPath path = BuildBallPath(own, c, positions, params);
  std::vector<HoldingFinding> findings;
  for (int i = 0; i < path.count; ++i) {
    const FuzzyTrajectory& t = path.trajectories[i];
    if (t.kick == nullptr || t.kicker < 0) continue;
    const std::size_t end = IndexOf(c, t.kicker, t.kick);
    const std::size_t from = HoldStart(c, t.kicker, end);
    // Holding starts facing the ball: the getter from its place, a receiver towards the pass.
    const FuzzyTrajectory* pass_in = nullptr;
    for (int j = i - 1; j >= 0 && pass_in == nullptr; --j) {
      if (path.trajectories[j].receiver == t.kicker) pass_in = &path.trajectories[j];
    }
    const Vec2 ball_F = pass_in ? pass_in->end_F : c.p_F_ball;
    const double heading =
        pass_in ? HeadingTowards(pass_in->end_F, pass_in->start_F)
                : HeadingTowards(c.teammates[static_cast<std::size_t>(t.kicker)].p_F, ball_F);
    const HoldPlan plan = PlanHold(c, t.kicker, from, t, heading, ball_F, Vec2::Zero(), kicks, hold);
    if (plan.judged && plan.hold_s > hold.hold_limit_s) {
      findings.push_back({i, c.teammates[static_cast<std::size_t>(t.kicker)].id, t.kick->kick, plan.hold_s, plan.dribble_m, plan.turns_rad});
    }
  }
  return findings;
}

std::string DescribeFinding(const HoldingFinding& f, const HoldParams& hold) {
  char text[320];
  std::snprintf(text, sizeof text,
                "teammate %d holds the ball %.2f s before its kick %s (trajectory %d): dribbles "
                "%.2f m at %.2f m/s and turns %.0f deg at %.0f deg/s, beyond the ball-holding "
                "limit %.2f s",
                f.teammate, f.hold_s, f.kick.c_str(), f.trajectory, f.dribble_m,
                hold.dribble_speed_mps, f.turns_rad * kRadToDeg,
                hold.dribble_turn_radps * kRadToDeg, hold.hold_limit_s);
  return text;
}

}  // namespace foresight
