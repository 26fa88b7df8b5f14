// The opponents never leave their home regions (Ros et al. 2009, sec. 5.1.2), checked at every
// control step of many trials of both configurations against the reactive team, and the
// defender does go for the ball (it touches it in some trials).
#include "match/opponent_team.h"

#include <gtest/gtest.h>

#include "common/random.h"
#include "match/match.h"
#include "match/reactive_team.h"
#include "match/robot_motion.h"
#include "models/walk_command.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

TEST(OpponentTeamTest, OpponentsNeverLeaveTheirRegions) {
  const auto models = testing::ModelsDir();
  const FieldSpec field = LoadFieldSpec(models / "fields" / "four_legged.json");
  const SimulationParams sim = LoadSimulationParams("simulation", models);
  const RobotParams robot = LoadRobotParams("aibo_ers7", models);
  const KickModel kicks = LoadKickModel(models / "kicks" / "aibo_ers7.json");
  const ReactiveParams reactive = LoadReactiveParams("reactive", models);
  const CoarseKickExecutor executor(field, kicks.rolling_deceleration_mps2);
  int frames = 0, touches = 0;
  for (const char* name : {"dg", "2d"}) {
    for (bool mirrored : {false, true}) {
      MatchConfig config = LoadMatchConfig(name, models, field, sim, robot);
      if (mirrored) config = config.Mirrored();
      MatchSetup setup{&field,
                       &kicks,
                       &robot,
                       &sim,
                       &config,
                       &executor,
                       mirrored ? -1.0 : 1.0,
                       sim.control_step_s};
      for (std::size_t s = 0; s < config.scenarios.size(); ++s) {
        for (int trial = 0; trial < 10; ++trial) {
          ReactiveTeam attackers(reactive, field, kicks, robot, sim, 2);
          OpponentTeam opponents(config, field, kicks, robot, sim);
          const MatchTrialResult r = RunTrial(setup, config.scenarios[s], attackers, opponents,
                                              StreamKey(5, s * 100 + trial));
          for (int t : r.counters.opponent_touches) touches += t;
          for (const TraceFrame& f : r.trace) {
            ++frames;
            for (std::size_t o = 0; o < config.opponents.size(); ++o) {
              const Vec2& p = f.robots[2 + o].p_F;
              ASSERT_TRUE(config.opponents[o].region.Contains(p))
                  << name << (mirrored ? " mirrored" : "") << " scenario " << s + 1 << " trial "
                  << trial << " t " << f.time_s << ": " << config.opponents[o].name << " at ("
                  << p.x() << ", " << p.y() << ")";
            }
          }
        }
      }
    }
  }
  EXPECT_GT(frames, 10000);
  EXPECT_GT(touches, 50);  // they do play the ball
}

class OpponentDecisionTest : public ::testing::Test {
 protected:
  OpponentDecisionTest() {
    const auto models = testing::ModelsDir();
    field_ = LoadFieldSpec(models / "fields" / "four_legged.json");
    sim_ = LoadSimulationParams("simulation", models);
    robot_ = LoadRobotParams("aibo_ers7", models);
    kicks_ = LoadKickModel(models / "kicks" / "aibo_ers7.json");
    config_ = LoadMatchConfig("dg", models, field_, sim_, robot_);
  }
  Perception See(const Pose2& pose, const Vec2& ball) const {
    Perception p;
    p.pose = pose;
    p.p_F_ball = ball;
    p.teammates = {pose, Pose2{Vec2(2.4, 0.0), kPi}};
    p.attack_sign = -1.0;
    return p;
  }
  FieldSpec field_;
  SimulationParams sim_;
  RobotParams robot_;
  KickModel kicks_;
  MatchConfig config_;
};

TEST_F(OpponentDecisionTest, WaitsOnTheBoundaryNearestTheBallFacingIt) {
  OpponentTeam team(config_, field_, kicks_, robot_, sim_);
  const Pose2 at{Vec2(0.5, 0.0), kPi};
  const RobotCommand c = team.Decide(See(at, Vec2(-1.5, 0.8)));
  ASSERT_EQ(c.kind, CommandKind::kWalk);
  // One step of this command would reach (x_min, 0.8): the region's point nearest the ball.
  const Pose2 next = ApplyWalk(at, c.v_R_mps, c.turn_radps, {1e9, 1e9, 1e9, 1e9}, 0.04);
  EXPECT_NEAR(next.p_F.x(), config_.opponents[0].region.x_min_m, 1e-9);
  EXPECT_NEAR(next.p_F.y(), 0.8, 1e-9);
  EXPECT_NEAR(WrapAngle(next.theta_rad - HeadingTowards(at.p_F, Vec2(-1.5, 0.8))), 0.0, 1e-9);
}

TEST_F(OpponentDecisionTest, GrabsABallInReachAndClearsOrTurnsAwayFromABlocker) {
  OpponentTeam team(config_, field_, kicks_, robot_, sim_);
  const Pose2 at{Vec2(1.0, 0.0), kPi};
  const Vec2 ball = at.ToField(Vec2(robot_.body_radius_m + field_.ball.radius_m + 0.01, 0.0));
  EXPECT_EQ(team.Decide(See(at, ball)).kind, CommandKind::kGetBall);
  Perception holding = See(at, ball);
  holding.holding_ball = true;
  EXPECT_EQ(team.Decide(holding).kind, CommandKind::kKick);
  // An attacker standing 0.3 m in front of the ball blocks the clearance: turn first.
  holding.opponents = {Pose2{ball + Vec2(-0.3, 0.02), 0.0}};
  holding.time_s = 0.04;
  const RobotCommand turn = team.Decide(holding);
  EXPECT_EQ(turn.kind, CommandKind::kWalk);
  EXPECT_NE(turn.turn_radps, 0.0);
  // ... but not beyond the holding limit.
  holding.time_s = sim_.ball_holding_limit_s - robot_.kick_launch_s + 0.04;
  EXPECT_EQ(team.Decide(holding).kind, CommandKind::kKick);
}

TEST_F(OpponentDecisionTest, ADefenderFacingItsOwnGoalNeverClearsTowardsIt) {
  OpponentTeam team(config_, field_, kicks_, robot_, sim_);
  // Attackers attack +x, so the defenders' own goal is at +x: this one faces it, holding the ball.
  const Pose2 at{Vec2(1.0, 0.3), 0.0};
  Perception holding = See(at, at.ToField(Vec2(robot_.body_radius_m + field_.ball.radius_m, 0.0)));
  holding.holding_ball = true;
  const RobotCommand first = team.Decide(holding);
  ASSERT_EQ(first.kind, CommandKind::kWalk);  // turns with the ball: no kick points away enough
  EXPECT_GT(first.turn_radps, 0.0);           // towards the side line the ball is nearer (+y)
  // When the holding rule makes it kick, it kicks the kick that points most upfield: a head
  // kick to the side, never the forward kick at its own goal.
  holding.time_s = sim_.ball_holding_limit_s - robot_.kick_launch_s + 0.04;
  const RobotCommand kick = team.Decide(holding);
  ASSERT_EQ(kick.kind, CommandKind::kKick);
  EXPECT_NE(kicks_.kicks[static_cast<std::size_t>(kick.kick_index)].name, config_.clear_kick);
}

TEST_F(OpponentDecisionTest, ThePapersGoalieWaitsOnItsRegionsBoundaryAndGoesForABallInIt) {
  ASSERT_EQ(config_.goalie.model, GoalieModel::kRos2009);
  const FieldBox& box = config_.opponents[1].region;
  OpponentTeam team(config_, field_, kicks_, robot_, sim_);
  // Ball at midfield: the goalie walks to its region's point nearest the ball, facing it.
  const Pose2 at{Vec2(2.4, 0.0), kPi};
  Perception p = See(at, Vec2(0.0, 0.3));
  p.self = 1;
  const RobotCommand wait = team.Decide(p);
  ASSERT_EQ(wait.kind, CommandKind::kWalk);
  const Pose2 next = ApplyWalk(at, wait.v_R_mps, wait.turn_radps, {1e9, 1e9, 1e9, 1e9}, 0.04);
  EXPECT_NEAR(next.p_F.x(), box.x_min_m, 1e-9);
  EXPECT_NEAR(next.p_F.y(), 0.3, 1e-9);
  EXPECT_NEAR(WrapAngle(next.theta_rad - HeadingTowards(at.p_F, Vec2(0.0, 0.3))), 0.0, 1e-9);
  // A ball in its region, in reach in front: it grabs it (its touch ends the trial as a block).
  const Vec2 ball = at.ToField(Vec2(robot_.body_radius_m + field_.ball.radius_m + 0.01, 0.0));
  Perception near = See(at, ball);
  near.self = 1;
  EXPECT_EQ(team.Decide(near).kind, CommandKind::kGetBall);
  // It never blocks: that is rUNSWift's goalie, on request.
  MatchConfig runswift = config_;
  runswift.goalie.model = GoalieModel::kRunswift2005;
  OpponentTeam keeper(runswift, field_, kicks_, robot_, sim_);
  const RobotCommand guard = keeper.Decide(p);
  ASSERT_EQ(guard.kind, CommandKind::kWalk);
  const Pose2 guarded = ApplyWalk(at, guard.v_R_mps, guard.turn_radps, {1e9, 1e9, 1e9, 1e9}, 0.04);
  EXPECT_GT(guarded.p_F.x(), box.x_min_m + 0.05);  // it stays back on the ball-goal line
}

TEST_F(OpponentDecisionTest, ADefenderFacingUpfieldClearsAtOnceUnlessABodyBlocksTheLine) {
  OpponentTeam team(config_, field_, kicks_, robot_, sim_);
  const Pose2 at{Vec2(1.0, 0.0), kPi};
  const Vec2 ball = at.ToField(Vec2(robot_.body_radius_m + field_.ball.radius_m, 0.0));
  Perception holding = See(at, ball);
  holding.holding_ball = true;
  const RobotCommand kick = team.Decide(holding);
  ASSERT_EQ(kick.kind, CommandKind::kKick);
  EXPECT_EQ(kicks_.kicks[static_cast<std::size_t>(kick.kick_index)].name, config_.clear_kick);
  // An attacker adjacent to the ball in the kick's line: no kick into it.
  holding.opponents = {Pose2{ball + Vec2(-(robot_.body_radius_m + field_.ball.radius_m), 0.0), 0.0}};
  EXPECT_EQ(team.Decide(holding).kind, CommandKind::kWalk);
}

}  // namespace
}  // namespace foresight
