// The reactive team's decisions on hand-made perceptions, rule by rule (match/reactive_team.h):
// every robot chases until its teammate reports holding the ball; a supporter in the holder's
// way steps aside until it is the release distance out, one out of the way waits ahead of the
// ball; the holder kicks forward once aimed at the goal, shoots into the open part of the goal and not at the goalie, dodges
// an opponent ahead towards the middle (the same in the mirrored game) but not one behind the
// ball, and at the holding limit shoots only with the gap ahead, releasing the ball otherwise;
// after letting the ball go it does not grab it again within the regrab delay.
#include "match/reactive_team.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "match/robot_motion.h"
#include "models/walk_command.h"
#include "planner/ball_roll.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

class ReactiveTeamTest : public ::testing::Test {
 protected:
  ReactiveTeamTest() {
    const auto models = testing::ModelsDir();
    field_ = LoadFieldSpec(models / "fields" / "four_legged.json");
    kicks_ = LoadKickModel(models / "kicks" / "aibo_ers7_published.json");
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
  // Robot 0 holding the ball in front of it, facing heading_rad.
  Perception Holding(const Vec2& ball, double heading_rad, double time_s = 1.0) const {
    const double front = robot_.body_radius_m + field_.ball.radius_m;
    Perception p = See(0, Pose2{ball - front * UnitVector(heading_rad), heading_rad}, ball, time_s);
    p.holding_ball = true;
    p.teammates = {p.pose, Pose2{Vec2(-2.0, -1.5), 0.0}};
    return p;
  }
  static std::vector<TeamMessage> Report(int sender, int kind, double distance_m, double t) {
    return {TeamMessage{sender, t, kind, Vec2(0.0, 0.0), distance_m}};
  }
  const KickSpec& Kick(const std::string& name) const {
    return kicks_.kicks[static_cast<std::size_t>(*kicks_.Find(name))];
  }
  double Roll(const std::string& name) const {
    const KickSpec& k = Kick(name);
    return k.launch_offset_m + StopDistance(k.speed_mps, kicks_.rolling_deceleration_mps2);
  }

  FieldSpec field_;
  KickModel kicks_;
  RobotParams robot_;
  ReactiveParams params_;
  SimulationParams sim_;
};

TEST_F(ReactiveTeamTest, EveryoneChasesUntilTheOwnerReportsThenTheOneInTheWayStepsAside) {
  ReactiveTeam team = Team();
  const Vec2 ball(0.0, 0.0);
  // Robot 0 reports chasing: robot 1, 0.5 m ahead of the ball, chases too.
  Perception p = See(1, Pose2{Vec2(0.5, 0.1), kPi}, ball, 0.04);
  const auto chasing = Report(0, 1, 0.2, 0.0);
  p.inbox = chasing;
  EXPECT_EQ(team.Decide(p).kind, CommandKind::kGetBall);
  // Robot 0 reports holding the ball: robot 1 stands 0.1 m off the line from the ball to the
  // goal, between them: it steps aside, to its own side (+y), backing up.
  p = See(1, Pose2{Vec2(0.5, 0.1), kPi}, ball, 0.08);
  const auto holding = Report(0, 2, 0.0, 0.08);
  p.inbox = holding;
  RobotCommand c = team.Decide(p);
  EXPECT_TRUE(c.backing_up);
  ASSERT_EQ(c.kind, CommandKind::kWalk);
  const Pose2 next = ApplyWalk(p.pose, c.v_R_mps, c.turn_radps, {1e9, 1e9, 1e9, 1e9}, 0.04);
  EXPECT_NEAR(next.p_F.y(), 0.1 + params_.step_aside_m, 1e-9);
  // 0.7 m off the line: still backing up (release at 0.6 + 0.2 m); 0.85 m: done.
  c = team.Decide(See(1, Pose2{Vec2(0.5, 0.7), kPi}, ball, 0.12));
  EXPECT_TRUE(c.backing_up);
  c = team.Decide(See(1, Pose2{Vec2(0.5, 0.85), kPi}, ball, 0.16));
  EXPECT_FALSE(c.backing_up);
  // Behind the ball it is in nobody's way.
  c = Team().Decide([&] {
    Perception q = See(1, Pose2{Vec2(-0.3, 0.0), 0.0}, ball, 0.12);
    q.inbox = holding;
    return q;
  }());
  EXPECT_FALSE(c.backing_up);
}

TEST_F(ReactiveTeamTest, SupporterMovesTowardsTheAttackingGoalBesideTheLine) {
  for (double sign : {1.0, -1.0}) {
    ReactiveTeam team = Team();
    // B (robot 1) below a ball on the middle line while A holds it: it walks to the point
    // support_ahead_m ahead of the ball and support_side_m to its own side.
    const Vec2 ball(sign * -1.0, 0.0);
    Perception p = See(1, Pose2{Vec2(sign * -1.5, -0.9), 0.0}, ball, 0.04);
    const auto told = Report(0, 2, 0.16, 0.0);
    p.inbox = told;
    p.attack_sign = sign;
    const RobotCommand c = team.Decide(p);
    ASSERT_EQ(c.kind, CommandKind::kWalk);
    EXPECT_FALSE(c.backing_up);
    const Pose2 next = ApplyWalk(p.pose, c.v_R_mps, c.turn_radps, {1e9, 1e9, 1e9, 1e9}, 0.04);
    EXPECT_NEAR(next.p_F.x(), sign * (-1.0 + params_.support_ahead_m), 1e-9) << sign;
    EXPECT_NEAR(next.p_F.y(), -params_.support_side_m, 1e-9) << sign;
  }
}

TEST_F(ReactiveTeamTest, FarFromTheGoalItTurnsToTheGoalAndKicksForward) {
  // Facing the goal from midfield: the power kick's mean roll (2.2 m) ends in the field: kicked.
  ReactiveTeam team = Team();
  RobotCommand c = team.Decide(Holding(Vec2(-1.5, 0.0), 0.0));
  ASSERT_EQ(c.kind, CommandKind::kKick);
  EXPECT_EQ(kicks_.kicks[static_cast<std::size_t>(c.kick_index)].name, "forward");
  // Facing 20 deg off: it turns on the spot with the ball instead.
  c = Team().Decide(Holding(Vec2(-1.5, 0.0), 20.0 * kDegToRad));
  ASSERT_EQ(c.kind, CommandKind::kWalk);
  EXPECT_LT(c.turn_radps, 0.0);
  EXPECT_EQ(c.v_R_mps.x(), 0.0);
  // Near the side line the goal centre lies 30 deg off: it kicks once aimed there, and the
  // kick's mean roll ends in the field.
  const Vec2 ball(-0.3, 1.7);
  const double heading = HeadingTowards(ball, Vec2(field_.HalfLength(), 0.0));
  ASSERT_GT(field_.HalfLength() - ball.x(), Roll("forward"));
  c = Team().Decide(Holding(ball, heading));
  ASSERT_EQ(c.kind, CommandKind::kKick);
  const Vec2 rest = ball + Roll("forward") * UnitVector(heading);
  EXPECT_LT(std::abs(rest.y()), field_.HalfWidth());
  EXPECT_LT(rest.x(), field_.HalfLength());
}

TEST_F(ReactiveTeamTest, NearTheGoalItShootsIntoTheGapBesideTheGoalieNotAtIt) {
  const double x = field_.HalfLength() - 1.0;  // within the power kick's roll of the line
  // The goalie 0.3 m before the goal line, 0.2 m to the left of centre: the open part of the
  // mouth is on the right.
  const Pose2 goalie{Vec2(field_.HalfLength() - 0.3, 0.2), kPi};
  Perception p = Holding(Vec2(x, 0.0), 0.0);
  p.opponents = {goalie};
  RobotCommand c = Team().Decide(p);
  ASSERT_EQ(c.kind, CommandKind::kWalk);  // facing the goalie: it turns right, to the gap
  EXPECT_LT(c.turn_radps, 0.0);
  // Facing into the right gap, a fifth of its width to spare: it shoots.
  const auto gap = BestGoalGap(field_, 1.0, p.p_F_ball, p.opponents, robot_.body_radius_m);
  ASSERT_TRUE(gap.has_value());
  EXPECT_LT(gap->Centre(), 0.0);
  EXPECT_FALSE(gap->Contains(0.0, params_.gap_padding));
  p = Holding(Vec2(x, 0.0), gap->Centre());
  p.opponents = {goalie};
  c = Team().Decide(p);
  ASSERT_EQ(c.kind, CommandKind::kKick);
  EXPECT_EQ(kicks_.kicks[static_cast<std::size_t>(c.kick_index)].name, params_.shoot_kick);
}

TEST_F(ReactiveTeamTest, DodgesAnOpponentAheadTowardsTheMiddleInBothDirectionsNotOneBehind) {
  for (double sign : {1.0, -1.0}) {
    const Vec2 ball(sign * 0.5, 1.0);
    Perception p = Holding(ball, sign > 0 ? 0.0 : kPi);
    p.attack_sign = sign;
    p.opponents = {Pose2{Vec2(sign * 0.8, 1.0), 0.0}};
    const RobotCommand c = Team().Decide(p);
    ASSERT_EQ(c.kind, CommandKind::kWalk);
    // Turning towards y = 0: clockwise when attacking +x, counter-clockwise when attacking -x.
    EXPECT_LT(sign * c.turn_radps, 0.0) << "attack sign " << sign;
    // An opponent as near but behind the ball blocks no forward kick: aimed at the goal, it kicks.
    Perception q = Holding(ball, HeadingTowards(ball, Vec2(sign * field_.HalfLength(), 0.0)));
    q.attack_sign = sign;
    q.opponents = {Pose2{Vec2(sign * 0.2, 0.8), 0.0}};
    EXPECT_EQ(Team().Decide(q).kind, CommandKind::kKick) << "attack sign " << sign;
  }
}

TEST_F(ReactiveTeamTest, AtTheHoldingLimitItShootsOnlyWithTheGapAheadAndReleasesOtherwise) {
  const double held_s = sim_.ball_holding_limit_s - robot_.kick_launch_s;
  // Dodging an opponent when the limit comes, facing the side line: it lets the ball go.
  ReactiveTeam team = Team();
  Perception p = Holding(Vec2(0.0, 0.5), 0.0, 1.0);
  p.opponents = {Pose2{Vec2(0.3, 0.5), kPi}};
  EXPECT_EQ(team.Decide(p).kind, CommandKind::kWalk);
  p = Holding(Vec2(0.0, 0.5), 0.5 * kPi, 1.0 + held_s);
  p.opponents = {Pose2{Vec2(0.3, 0.5), kPi}};
  EXPECT_EQ(team.Decide(p).kind, CommandKind::kRelease);
  // Near the goal facing inside the goal's mouth (with the goalie beside the aim): the shot.
  ReactiveTeam near = Team();
  const double x = field_.HalfLength() - 0.8;
  Perception q = Holding(Vec2(x, 0.0), 0.0, 1.0);
  q.opponents = {Pose2{Vec2(x + 0.3, 0.0), kPi}};  // in front: it dodges until the limit
  EXPECT_EQ(near.Decide(q).kind, CommandKind::kWalk);
  q = Holding(Vec2(x, 0.0), -0.1, 1.0 + held_s);
  q.opponents = {Pose2{Vec2(field_.HalfLength() - 0.2, 0.25), kPi}};
  EXPECT_EQ(near.Decide(q).kind, CommandKind::kKick);
}

TEST_F(ReactiveTeamTest, AfterLettingTheBallGoItFollowsItWithoutGrabbingForTheRegrabDelay) {
  ReactiveTeam team = Team();
  // It kicks at t = 1 s ...
  ASSERT_EQ(team.Decide(Holding(Vec2(-1.5, 0.0), 0.0, 1.0)).kind, CommandKind::kKick);
  // ... then chases a ball right in front of it: it walks, and grabs only after the delay.
  const Pose2 pose{Vec2(-1.0, 0.0), 0.0};
  EXPECT_EQ(team.Decide(See(0, pose, Vec2(-0.8, 0.0), 1.5)).kind, CommandKind::kWalk);
  EXPECT_EQ(team.Decide(See(0, pose, Vec2(-0.8, 0.0), 1.0 + params_.regrab_delay_s)).kind,
            CommandKind::kGetBall);
}

}  // namespace
}  // namespace foresight
