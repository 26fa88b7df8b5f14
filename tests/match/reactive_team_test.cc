// The reactive team's decisions on hand-made perceptions: every robot chases until its teammate
// reports that it holds the ball; a supporter near the ball then backs up until it is the
// release distance away; the
// holder kicks within its kick's reach of the goal line when facing the goal and no opponent is
// within the dodge radius of the ball, dodges an
// opponent ahead towards the middle of the field (the same in the mirrored game), and kicks at
// the hold limit.
#include "match/reactive_team.h"

#include <gtest/gtest.h>

#include <vector>

#include "match/robot_motion.h"
#include "planner/ball_roll.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

class ReactiveTeamTest : public ::testing::Test {
 protected:
  ReactiveTeamTest() {
    const auto models = testing::ModelsDir();
    field_ = LoadFieldSpec(models / "fields" / "four_legged.json");
    kicks_ = LoadKickModel(models / "kicks" / "aibo_ers7.json");
    robot_ = LoadRobotParams("aibo_ers7", models);
    params_ = LoadReactiveParams("reactive", models);
    sim_ = LoadSimulationParams("simulation", models);
  }
  ReactiveTeam Team() const { return ReactiveTeam(params_, field_, kicks_, robot_, sim_, 2); }
  Perception See(int self, const Pose2& pose, const Vec2& ball, double time_s = 0.0) const {
    Perception p;
    p.time_s = time_s;
    p.self = self;
    p.pose = pose;
    p.p_F_ball = ball;
    p.teammates = {pose, pose};
    return p;
  }
  static std::vector<TeamMessage> Report(int sender, int kind, double distance_m, double t) {
    return {TeamMessage{sender, t, kind, Vec2(0.0, 0.0), distance_m}};
  }

  FieldSpec field_;
  KickModel kicks_;
  RobotParams robot_;
  ReactiveParams params_;
  SimulationParams sim_;
};

TEST_F(ReactiveTeamTest, EveryoneChasesUntilTheOwnerReportsThenTheOthersBackUp) {
  ReactiveTeam team = Team();
  const Vec2 ball(0.0, 0.0);
  // Robot 0 reports chasing from 0.2 m: robot 1, 0.5 m away, chases too (no claim by distance).
  Perception p = See(1, Pose2{Vec2(-0.5, 0.0), 0.0}, ball, 0.04);
  const auto chasing = Report(0, 1, 0.2, 0.0);
  p.inbox = chasing;
  EXPECT_EQ(team.Decide(p).kind, CommandKind::kGetBall);
  // Robot 0 reports holding the ball: robot 1 backs up.
  p = See(1, Pose2{Vec2(-0.5, 0.0), 0.0}, ball, 0.08);
  const auto holding = Report(0, 2, 0.0, 0.08);
  p.inbox = holding;
  RobotCommand c = team.Decide(p);
  EXPECT_TRUE(c.backing_up);  // 0.5 m < back_off_distance_m (0.6)
  EXPECT_EQ(c.kind, CommandKind::kWalk);
  EXPECT_LT(c.v_R_mps.x(), 0.0);  // walks away from the ball, backwards
  // 0.7 m away: still backing up (release at 0.6 + 0.2 m); 0.85 m: done.
  c = team.Decide(See(1, Pose2{Vec2(-0.7, 0.0), 0.0}, ball, 0.12));
  EXPECT_TRUE(c.backing_up);
  c = team.Decide(See(1, Pose2{Vec2(-0.85, 0.0), 0.0}, ball, 0.16));
  EXPECT_FALSE(c.backing_up);
  // The owner kicked and reports chasing again: robot 1 goes for the ball.
  p = See(1, Pose2{Vec2(-0.85, 0.0), 0.0}, ball, 0.2);
  const auto released = Report(0, 1, 0.3, 0.2);
  p.inbox = released;
  EXPECT_EQ(team.Decide(p).kind, CommandKind::kGetBall);
}

TEST_F(ReactiveTeamTest, SupporterWaitsInsideItsRoleRegion) {
  for (double sign : {1.0, -1.0}) {
    ReactiveTeam team = Team();
    // B (robot 1, region y <= 0.6 m) above a ball at y = 1.0 while A holds it: the support point
    // 0.8 m further up is outside B's region; B goes to its edge instead.
    const Vec2 ball(sign * 0.5, 1.0);
    Perception p = See(1, Pose2{Vec2(sign * -0.5, 1.2), 0.0}, ball, 0.04);
    const auto told = Report(0, 2, 0.16, 0.0);
    p.inbox = told;
    p.attack_sign = sign;
    const RobotCommand c = team.Decide(p);
    ASSERT_EQ(c.kind, CommandKind::kWalk);
    EXPECT_FALSE(c.backing_up);
    const Pose2 next = ApplyWalk(p.pose, c.v_R_mps, c.turn_radps, {1e9, 1e9}, 0.04);
    EXPECT_NEAR(next.p_F.y(), params_.role_regions[1].y_max_m, 1e-9) << sign;
    EXPECT_NEAR(next.p_F.x(), sign * (0.5 - params_.support_behind_m), 1e-9) << sign;
  }
}

TEST_F(ReactiveTeamTest, HolderShootsWithinItsKicksReachFacingTheGoal) {
  const double reach = StopDistance(kicks_.kicks[0].speed_mps, kicks_.rolling_deceleration_mps2);
  const double x = field_.HalfLength() - reach + 0.05;
  ReactiveTeam team = Team();
  Perception p = See(0, Pose2{Vec2(x - 0.16, 0.0), 0.0}, Vec2(x, 0.0), 1.0);
  p.holding_ball = true;
  EXPECT_EQ(team.Decide(p).kind, CommandKind::kKick);
  // Further out it walks with the ball instead.
  ReactiveTeam far = Team();
  Perception q = See(0, Pose2{Vec2(0.0, 0.0), 0.0}, Vec2(0.16, 0.0), 1.0);
  q.holding_ball = true;
  const RobotCommand walk = far.Decide(q);
  EXPECT_EQ(walk.kind, CommandKind::kWalk);
  EXPECT_GT(walk.v_R_mps.x(), 0.0);
  // An opponent within the dodge radius blocks the shot (Ros et al. 2009, sec. 5.3.1): it dodges.
  ReactiveTeam blocked = Team();
  Perception b = p;
  b.opponents = {Pose2{Vec2(x + params_.dodge_radius_m - 0.05, 0.0), kPi}};
  EXPECT_EQ(blocked.Decide(b).kind, CommandKind::kWalk);
  // One just outside it does not.
  b.opponents = {Pose2{Vec2(x + params_.dodge_radius_m + 0.05, 0.0), kPi}};
  EXPECT_EQ(Team().Decide(b).kind, CommandKind::kKick);
  // And kicks once it has held the ball for the hold limit minus the kick's time.
  q.time_s = 1.0 + sim_.ball_holding_limit_s - robot_.kick_launch_s;
  EXPECT_EQ(far.Decide(q).kind, CommandKind::kKick);
}

TEST_F(ReactiveTeamTest, DodgesAnOpponentDeadAheadTowardsTheMiddleInBothDirections) {
  for (double sign : {1.0, -1.0}) {
    ReactiveTeam team = Team();
    const Vec2 ball(sign * 0.5, 1.0);
    Perception p = See(0, Pose2{Vec2(sign * 0.34, 1.0), sign > 0 ? 0.0 : kPi}, ball, 1.0);
    p.holding_ball = true;
    p.attack_sign = sign;
    p.opponents = {Pose2{Vec2(sign * 0.8, 1.0), 0.0}};
    const RobotCommand c = team.Decide(p);
    ASSERT_EQ(c.kind, CommandKind::kWalk);
    // Turning towards y = 0: clockwise when attacking +x, counter-clockwise when attacking -x.
    EXPECT_LT(sign * c.turn_radps, 0.0) << "attack sign " << sign;
  }
}

}  // namespace
}  // namespace foresight
