// The kick race (cbr/kick_race.h): the getter's time to play the ball away, worked by hand, the
// holding limit, the held path a dribble adds, and the cases it does not judge.
#include "cbr/kick_race.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace foresight {
namespace {

constexpr double kPi = std::numbers::pi;
const RaceParams kRace{0.3, 0.16, 0.04};
// grab 0.3 s, dribble 0.15 m/s, turn with the ball 45 deg/s, hold limit 2.4 s, launch 0.3 s.
const HoldParams kHold{0.3, 0.15, kPi / 4.0, 2.4, 0.3};

CaseAction Act(ActionType type) {
  CaseAction a;
  a.type = type;
  return a;
}

// A kick model whose "side" kick leaves 90 degrees to the robot's left.
KickModel Kicks() {
  KickModel m;
  m.kicks.push_back({"forward", 2.0, 0.1, 0.0, 0.05});
  m.kicks.push_back({"side", 1.0, 0.1, kPi / 2.0, 0.05});
  return m;
}

// One attacker behind the ball (the case's ball at the origin) plays `before`, then kicks `kick`
// at target (2, 0) of the case.
Case OneKick(const std::vector<CaseAction>& before, const std::string& kick) {
  Case c;
  c.defending = DefendingGoal::kCyan;
  c.p_F_ball = Vec2(0.0, 0.0);
  std::vector<CaseAction> actions{Act(ActionType::kGetBall)};
  actions.insert(actions.end(), before.begin(), before.end());
  CaseAction k = Act(ActionType::kKick);
  k.kick = kick;
  k.target_F = Vec2(2.0, 0.0);
  actions.push_back(k);
  c.teammates.push_back({1, {-0.3, 0.0}, actions});
  return c;
}

struct Played {
  Problem problem;
  Correspondence match;
  CaseBallPath path;
};

// The problem: the ball at the origin, the getter at `getter_F` facing +x, the opponents.
Played Play(const Case& c, const Vec2& getter_F, const std::vector<Vec2>& opponents) {
  Played p;
  p.problem.p_F_ball = Vec2(0.0, 0.0);
  p.problem.teammates.push_back({1, Pose2{getter_F, 0.0}});
  for (const Vec2& o : opponents) p.problem.opponents.push_back(o);
  p.match.count = 1;
  p.match.problem_index[0] = 0;
  p.match.adapted_F[0] = getter_F;
  p.match.feasible = true;
  const RetrievalParams params;
  p.path = BuildBallPath(p.problem, c, std::span<const Vec2>(p.match.adapted_F.data(), 1), params);
  return p;
}

TEST(KickRaceTest, AStraightKickFromBehindTheBallNeedsOnlyTheWalkGrabAndLaunch) {
  const Case c = OneKick({}, "forward");
  const Played p = Play(c, Vec2(-1.0, 0.0), {Vec2(0.0, 2.0)});
  const KickRace r = RunKickRace(p.problem, c, p.match, 0, p.path, Kicks(), kRace, kHold);
  ASSERT_TRUE(r.judged);
  EXPECT_NEAR(r.hold_s, 0.0, 1e-12);  // it walks along +x and kicks along +x: no turn
  EXPECT_NEAR(r.kick_s, (1.0 - 0.16) / 0.3 + 0.3 + 0.3, 1e-12);
  EXPECT_NEAR(r.opponents_s, (2.0 - 0.16) / 0.3, 1e-12);
  EXPECT_TRUE(r.won);  // 3.4 s against 6.13 s
}

TEST(KickRaceTest, ASideKickAimsAQuarterTurnAwayAndLosesToACloseOpponent) {
  const Case c = OneKick({}, "side");
  // The side kick leaves 90 degrees left of the heading: to kick along +x the robot faces -y,
  // a quarter turn from its walk along +x: 2 s at 45 deg/s.
  const Played near = Play(c, Vec2(-0.16, 0.0), {Vec2(0.0, 0.8)});
  const KickRace r = RunKickRace(near.problem, c, near.match, 0, near.path, Kicks(), kRace, kHold);
  EXPECT_NEAR(r.hold_s, 2.0, 1e-9);
  EXPECT_NEAR(r.kick_s, 0.0 + 0.3 + 2.0 + 0.3, 1e-9);
  EXPECT_NEAR(r.opponents_s, (0.8 - 0.16) / 0.3, 1e-12);  // 2.13 s < 2.6 s
  EXPECT_FALSE(r.won);
  // The same opponent 0.2 m farther arrives in 2.8 s: too late.
  const Played far = Play(c, Vec2(-0.16, 0.0), {Vec2(0.0, 1.0)});
  EXPECT_TRUE(RunKickRace(far.problem, c, far.match, 0, far.path, Kicks(), kRace, kHold).won);
}

TEST(KickRaceTest, ADribbleAddsItsWalkAndTheOpponentMeetsTheBallAnywhereOnIt) {
  CaseAction dribble = Act(ActionType::kDribble);
  dribble.target_F = Vec2(0.0, 0.3);  // a quarter turn left, then 0.3 m: 2 + 2 s, then capped
  const Case c = OneKick({dribble}, "forward");
  const Played p = Play(c, Vec2(-0.16, 0.0), {Vec2(1.0, 0.3)});
  const KickRace r = RunKickRace(p.problem, c, p.match, 0, p.path, Kicks(), kRace, kHold);
  ASSERT_TRUE(r.judged);
  EXPECT_TRUE(r.kick_spot_F.isApprox(Vec2(0.0, 0.3)));
  // 2 s turn + 2 s walk + 2 s turn back to +x: 6 s, capped by the holding limit.
  EXPECT_NEAR(r.hold_s, 2.4, 1e-12);
  EXPECT_NEAR(r.kick_s, 0.3 + 2.4 + 0.3, 1e-12);
  // The opponent is 1.0 m from the dribble's end, 1.04 m from the ball now: there in 2.8 s,
  // before the kick at 3.0 s.
  EXPECT_NEAR(r.opponents_s, (1.0 - 0.16) / 0.3, 1e-12);
  EXPECT_FALSE(r.won);
}

TEST(KickRaceTest, AnOpponentBesideTheDribbleIsMeasuredFromTheSegment) {
  CaseAction dribble = Act(ActionType::kDribble);
  dribble.target_F = Vec2(0.6, 0.0);
  const Case c = OneKick({dribble}, "forward");
  const Played p = Play(c, Vec2(-0.16, 0.0), {Vec2(0.3, 0.5)});
  const KickRace r = RunKickRace(p.problem, c, p.match, 0, p.path, Kicks(), kRace, kHold);
  EXPECT_NEAR(r.opponents_s, (0.5 - 0.16) / 0.3, 1e-12);  // 0.5 m from the segment's middle
  EXPECT_NEAR(r.hold_s, 2.4, 1e-12);                      // 4 s of dribble, capped
  EXPECT_FALSE(r.won);
}

TEST(KickRaceTest, TheGetterGoesByItsAdaptedPositionAndAimsASideKickOffItsHeading) {
  const Case c = OneKick({}, "side");
  Played p = Play(c, Vec2(-1.0, 0.0), {});
  p.match.adapted_F[0] = Vec2(-0.1, -0.1);  // next to the ball, on its lower left
  const HoldParams long_hold{0.3, 0.15, kPi / 4.0, 10.0, 0.3};
  const KickRace r = RunKickRace(p.problem, c, p.match, 0, p.path, Kicks(), kRace, long_hold);
  // It grabs facing +45 deg (from its adapted position); the side kick leaves 90 deg to the
  // robot's left, so to kick along +x it faces -90 deg: a 135 deg turn, 3 s (45 deg the other
  // way, had the kick's direction the wrong sign).
  EXPECT_NEAR(r.hold_s, 3.0, 1e-9);
  const double walk_s = std::sqrt(0.9 * 0.9 + 0.1 * 0.1) / 0.3;  // to (-0.1, -0.1), at the ball
  EXPECT_NEAR(r.kick_s, walk_s + 0.3 + 3.0 + 0.3, 1e-9);
}

TEST(KickRaceTest, WithoutOpponentsTheGetterWins) {
  const Case c = OneKick({}, "side");
  const Played p = Play(c, Vec2(-1.0, 0.0), {});
  const KickRace r = RunKickRace(p.problem, c, p.match, 0, p.path, Kicks(), kRace, kHold);
  EXPECT_TRUE(std::isinf(r.opponents_s));
  EXPECT_TRUE(r.won);
}

TEST(KickRaceTest, AWaitBeforeTheKickOrNoKickIsNotJudged) {
  const Case waits = OneKick({Act(ActionType::kWait)}, "forward");
  const Played p = Play(waits, Vec2(-0.16, 0.0), {Vec2(0.0, 0.2)});
  const KickRace r = RunKickRace(p.problem, waits, p.match, 0, p.path, Kicks(), kRace, kHold);
  EXPECT_FALSE(r.judged);
  EXPECT_TRUE(r.won);
  Case no_kick;
  no_kick.p_F_ball = Vec2(0.0, 0.0);
  no_kick.teammates.push_back({1, {-0.3, 0.0}, {Act(ActionType::kGetBall)}});
  const Played q = Play(no_kick, Vec2(-0.16, 0.0), {Vec2(0.0, 0.2)});
  EXPECT_FALSE(RunKickRace(q.problem, no_kick, q.match, 0, q.path, Kicks(), kRace, kHold).judged);
}

}  // namespace
}  // namespace foresight
