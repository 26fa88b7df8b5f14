// The simulator with scripted policies: a ball kicked into a standing opponent with restitution 0
// stops at its body and counts one touch (rebounds: tests/match/ball_motion_test.cc); a goalie's touch ends the trial as a block; a trial is the same for the
// same key; opponents played by OpponentTeam never leave their home regions.
#include "match/match.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "match/opponent_team.h"
#include "match/reactive_team.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

// Attacker 0 gets the ball and kicks it with kick 0 (or releases it) as soon as it holds it; the
// rest stand.
class GetAndKick final : public TeamPolicy {
 public:
  explicit GetAndKick(CommandKind then = CommandKind::kKick) : then_(then) {}
  RobotCommand Decide(const Perception& p) override {
    RobotCommand c;
    if (p.self != 0 || p.busy || kicked_) return c;
    if (p.holding_ball) {
      c.kind = then_;
      c.kick_index = then_ == CommandKind::kKick ? 0 : kNoKick;
      kicked_ = true;
    } else {
      c.kind = CommandKind::kGetBall;
    }
    return c;
  }

 private:
  CommandKind then_;
  bool kicked_ = false;
};

class Stand final : public TeamPolicy {
 public:
  RobotCommand Decide(const Perception&) override { return {}; }
};

class MatchTest : public ::testing::Test {
 protected:
  MatchTest() {
    const auto models = testing::ModelsDir();
    field_ = LoadFieldSpec(models / "fields" / "four_legged.json");
    sim_ = LoadSimulationParams("simulation", models);
    robot_ = LoadRobotParams("aibo_ers7", models);
    robot_.grab_failure_rate = 0.0;
    kicks_.robot = "test";
    kicks_.rolling_deceleration_mps2 = 0.3;
    kicks_.kicks = {{"straight", 1.0, 0.0, 0.0, 0.0}};
    config_.name = "test";
    config_.time_limit_s = 10.0;
    config_.opponents = {{"D", OpponentRole::kDefender, {-2.0, 1.9, -1.5, 1.5}}};
    executor_ = std::make_unique<CoarseKickExecutor>(field_, kicks_.rolling_deceleration_mps2);
    setup_.field = &field_;
    setup_.kicks = &kicks_;
    setup_.robot = &robot_;
    setup_.sim = &sim_;
    setup_.config = &config_;
    setup_.executor = executor_.get();
  }
  // Attacker and defender face each other with the ball between them.
  static Scenario NoseToNose() {
    return Scenario{"fight",
                    Vec2(0.0, 0.0),
                    {Pose2{Vec2(-0.2, 0.0), 0.0}, Pose2{Vec2(-2.0, -1.0), 0.0}},
                    {Pose2{Vec2(0.2, 0.0), kPi}}};
  }
  Scenario OneOpponentAhead(double opponent_x) const {
    return Scenario{"test",
                    Vec2(0.0, 0.0),
                    {Pose2{Vec2(-0.2, 0.0), 0.0}, Pose2{Vec2(-1.0, -1.0), 0.0}},
                    {Pose2{Vec2(opponent_x, 0.0), kPi}}};
  }

  FieldSpec field_;
  SimulationParams sim_;
  RobotParams robot_;
  KickModel kicks_;
  MatchConfig config_;
  std::unique_ptr<KickExecutor> executor_;
  MatchSetup setup_;
};

TEST_F(MatchTest, BallKickedIntoARobotWithoutRestitutionStopsAtItAndCountsOneTouch) {
  setup_.robot_restitution = 0.0;  // fully inelastic: the ball keeps no normal speed
  GetAndKick attackers;
  Stand opponents;
  const MatchTrialResult r = RunTrial(setup_, OneOpponentAhead(1.0), attackers, opponents, 7);
  EXPECT_EQ(r.outcome, TrialOutcome::kTimeout);
  EXPECT_EQ(r.counters.attacker_kicks[0], 1);
  EXPECT_EQ(r.counters.opponent_touches[0], 1);
  EXPECT_EQ(r.counters.opponent_kicks[0], 0);
  const MatchEvent& end = r.events.back();
  EXPECT_EQ(end.kind, EventKind::kEnd);
  // The 1 m/s kick would roll 1.67 m; it stops at the opponent's body instead.
  EXPECT_NEAR(end.p_F_ball.x(), 1.0 - robot_.body_radius_m - field_.ball.radius_m, 1e-6);
}

TEST_F(MatchTest, OpenFieldKickInAMatchRollsVSquaredOverTwoA) {
  GetAndKick attackers;
  Stand opponents;
  const MatchTrialResult r = RunTrial(setup_, OneOpponentAhead(-2.0), attackers, opponents, 7);
  double kick_x = 0.0;
  for (const MatchEvent& e : r.events) {
    if (e.kind == EventKind::kKick) kick_x = e.p_F_ball.x();
  }
  EXPECT_EQ(r.counters.opponent_touches[0], 0);
  EXPECT_NEAR(r.events.back().p_F_ball.x() - kick_x, 1.0 / (2.0 * 0.3), 1e-9);
}

TEST_F(MatchTest, GoalieTouchIsABlock) {
  config_.opponents[0].role = OpponentRole::kGoalie;
  GetAndKick attackers;
  Stand opponents;
  const MatchTrialResult r = RunTrial(setup_, OneOpponentAhead(1.0), attackers, opponents, 7);
  EXPECT_EQ(r.outcome, TrialOutcome::kBlock);
}

TEST_F(MatchTest, SameKeySameTrialOtherKeyOtherTrial) {
  const auto models = testing::ModelsDir();
  const ReactiveParams reactive = LoadReactiveParams("reactive", models);
  const KickModel aibo = LoadKickModel(models / "kicks" / "aibo_ers7.json");
  const MatchConfig dg = LoadMatchConfig("dg", models, field_, sim_, robot_);
  robot_.grab_failure_rate = 0.2;
  setup_.kicks = &aibo;
  setup_.config = &dg;
  auto play = [&](std::uint64_t key) {
    ReactiveTeam attackers(reactive, field_, aibo, robot_, sim_, 2);
    OpponentTeam opponents(dg, field_, aibo, robot_, sim_);
    return RunTrial(setup_, dg.scenarios[2], attackers, opponents, key);
  };
  const MatchTrialResult a = play(11), b = play(11), c = play(12);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].time_s, b.events[i].time_s);
    EXPECT_EQ(a.events[i].p_F_ball, b.events[i].p_F_ball);
  }
  EXPECT_NE(a.events.size() == c.events.size() && a.counters.time_s == c.counters.time_s &&
                a.events.back().p_F_ball == c.events.back().p_F_ball,
            true);
}

// Robot 0 sends a message every step; every robot records what it was told and what it saw.
class Recorder final : public TeamPolicy {
 public:
  RobotCommand Decide(const Perception& p) override {
    RobotCommand c;
    if (p.self == 0) c.message = TeamMessage{0, 0.0, 7, Vec2(0.0, 0.0), p.time_s};
    for (const TeamMessage& m : p.inbox) delays.push_back(p.time_s - m.value);
    if (p.self == 1) balls.push_back(p.p_F_ball);
    return c;
  }
  std::vector<double> delays;
  std::vector<Vec2> balls;
};

TEST_F(MatchTest, MessagesArriveAfterTheLatencyOrAreLost) {
  Recorder attackers;
  Stand opponents;
  sim_.message_latency_s = 0.2;
  RunTrial(setup_, OneOpponentAhead(1.0), attackers, opponents, 3);
  ASSERT_GT(attackers.delays.size(), 200u);
  for (double d : attackers.delays) EXPECT_NEAR(d, 0.2, 1e-9);
  sim_.message_loss_rate = 0.25;
  Recorder lossy;
  const MatchTrialResult r = RunTrial(setup_, OneOpponentAhead(1.0), lossy, opponents, 3);
  int lost = 0;
  for (const MatchEvent& e : r.events) lost += e.kind == EventKind::kMessageLost;
  const double sent = static_cast<double>(lost + static_cast<int>(lossy.delays.size()));
  EXPECT_NEAR(lost / sent, 0.25, 0.05);  // 250 messages: 4 sd of a binomial share
}

TEST_F(MatchTest, PerceptionNoiseHasTheGivenSigmaAndNoneByDefault) {
  Recorder exact;
  Stand opponents;
  RunTrial(setup_, OneOpponentAhead(1.0), exact, opponents, 3);
  for (const Vec2& b : exact.balls) EXPECT_EQ(b, Vec2(0.0, 0.0));
  sim_.ball_noise_sigma_m = 0.05;
  Recorder noisy;
  RunTrial(setup_, OneOpponentAhead(1.0), noisy, opponents, 3);
  double sum_sq = 0.0;
  for (const Vec2& b : noisy.balls) sum_sq += b.squaredNorm();
  const double sigma = std::sqrt(sum_sq / (2.0 * static_cast<double>(noisy.balls.size())));
  EXPECT_NEAR(sigma, 0.05, 0.005);  // 250 steps x 2 axes
}

// Every robot of the team goes for the ball and never lets it go: a fight that only the referee
// ends (robot 1 of the attackers stands).
class Grabber final : public TeamPolicy {
 public:
  RobotCommand Decide(const Perception& p) override {
    RobotCommand c;
    if (p.self == 0 && !p.busy && !p.holding_ball) c.kind = CommandKind::kGetBall;
    return c;
  }
};

TEST_F(MatchTest, TheRefereeEndsAFightForTheBallAfterTheHoldingLimitClearOfEveryBody) {
  robot_.steal_success_rate = 1.0;
  robot_.steal_cone_rad = kPi;  // the ball is taken from any side: the fight never ends itself
  config_.time_limit_s = 20.0;
  Grabber attackers, opponents;
  const MatchTrialResult r = RunTrial(setup_, NoseToNose(), attackers, opponents, 5);
  ASSERT_GT(r.counters.contests_resolved, 1);  // and again after each walk back to the ball
  std::vector<double> moved_s;
  for (const MatchEvent& e : r.events) {
    if (e.kind == EventKind::kBallMoved) moved_s.push_back(e.time_s);
  }
  ASSERT_EQ(static_cast<int>(moved_s.size()), r.counters.contests_resolved);
  // The first fight begins with the first grab and lasts the holding limit, to the step; no later
  // one is shorter.
  double first_grab_s = -1.0;
  for (const MatchEvent& e : r.events) {
    if (e.kind == EventKind::kGrab && first_grab_s < 0.0) first_grab_s = e.time_s;
  }
  ASSERT_GE(first_grab_s, 0.0);
  EXPECT_GT(moved_s.front() - first_grab_s, sim_.ball_holding_limit_s);
  EXPECT_LE(moved_s.front() - first_grab_s, sim_.ball_holding_limit_s + sim_.control_step_s + 1e-9);
  for (std::size_t i = 1; i < moved_s.size(); ++i) {
    EXPECT_GT(moved_s[i] - moved_s[i - 1], sim_.ball_holding_limit_s);
  }
}

TEST_F(MatchTest, FreeSpotIsClearOfEveryBody) {
  robot_.steal_success_rate = 1.0;
  robot_.steal_cone_rad = kPi;
  config_.time_limit_s = 5.0;
  setup_.trace_period_s = sim_.control_step_s;
  Grabber attackers, opponents;
  const MatchTrialResult r = RunTrial(setup_, NoseToNose(), attackers, opponents, 5);
  ASSERT_EQ(r.counters.contests_resolved, 1);
  for (const MatchEvent& e : r.events) {
    if (e.kind != EventKind::kBallMoved) continue;
    // The robots' poses at that step: the trace frame of the same time.
    for (const TraceFrame& f : r.trace) {
      if (std::abs(f.time_s - e.time_s) > 1e-9) continue;
      for (const Pose2& body : f.robots) {
        EXPECT_GE((e.p_F_ball - body.p_F).norm(),
                  robot_.body_radius_m + field_.ball.radius_m + sim_.contest_clearance_m - 1e-9);
      }
    }
  }
}

// Two opponents stand side by side between the attacker and the ball: the attacker, walking
// straight at the ball, is wedged in the notch between their bodies and the ball never moves.
// Only the league's local game stuck ends it.
Scenario Wedge() {
  return Scenario{"wedge",
                  Vec2(0.55, 0.0),
                  {Pose2{Vec2(-0.5, 0.0), 0.0}, Pose2{Vec2(-2.0, -1.0), 0.0}},
                  {Pose2{Vec2(0.3, 0.2), kPi}, Pose2{Vec2(0.3, -0.2), kPi}}};
}

// Records when the team decided for each robot.
class DecisionClock final : public TeamPolicy {
 public:
  RobotCommand Decide(const Perception& p) override {
    times_s[static_cast<std::size_t>(p.self)].push_back(p.time_s);
    return {};
  }
  std::vector<double> times_s[2];
};

TEST_F(MatchTest, LocalGameStuckPenalisesTheRobotClosestToAStillBallAtTheTouchline) {
  config_.opponents.push_back({"G", OpponentRole::kDefender, {-2.0, 1.9, -1.5, 1.5}});
  config_.time_limit_s = sim_.stuck_after_s + 3.0;
  setup_.trace_period_s = sim_.control_step_s;
  GetAndKick attackers(CommandKind::kRelease);
  Stand opponents;
  const MatchTrialResult r = RunTrial(setup_, Wedge(), attackers, opponents, 5);
  ASSERT_EQ(r.counters.stuck_penalties, 1);
  const MatchEvent* penalty = nullptr;
  bool grabbed_after = false, touched_before = false;
  for (const MatchEvent& e : r.events) {
    if (e.kind == EventKind::kPenalized) penalty = &e;
    touched_before = touched_before || (!penalty && e.kind == EventKind::kTouch);
    grabbed_after = grabbed_after || (penalty && e.kind == EventKind::kGrab && e.robot == 0);
  }
  ASSERT_NE(penalty, nullptr);
  EXPECT_FALSE(touched_before);  // wedged: the attacker never reached the ball
  // The ball lay still from the start: the call comes after stuck_after_s, to the step.
  EXPECT_NEAR(penalty->time_s, sim_.stuck_after_s, sim_.control_step_s + 1e-9);
  // The closest robots are the two opponents (edge 0.2 m; the attacker's 0.26 m): the first.
  EXPECT_EQ(penalty->side, Side::kOpponents);
  EXPECT_EQ(penalty->robot, 0);
  EXPECT_EQ(penalty->detail, "local_game_stuck");
  EXPECT_TRUE(grabbed_after);  // the way to the ball is open
  // At the touchline on its side (y > 0), by the front line of its own penalty area (+x).
  const TraceFrame* after = nullptr;
  for (const TraceFrame& f : r.trace) {
    if (!after && f.time_s > penalty->time_s - 1e-9) after = &f;
  }
  ASSERT_NE(after, nullptr);
  const Pose2& placed = after->robots[2];
  EXPECT_NEAR(placed.p_F.x(), field_.HalfLength() - sim_.penalty_area_depth_m, 1e-9);
  EXPECT_NEAR(placed.p_F.y(), field_.CarpetHalfWidth() - robot_.body_radius_m, 1e-9);
  EXPECT_NEAR(placed.theta_rad, -0.5 * kPi, 1e-12);  // facing the field
}

TEST_F(MatchTest, APenalisedRobotGetsNoDecisionsUntilItsPenaltyEnds) {
  sim_.stuck_penalty_s = 4.0;
  config_.time_limit_s = sim_.stuck_after_s + 6.0;
  Stand attackers;
  DecisionClock opponents;
  // The defender stands 0.1 m from the ball's edge; nobody else is near.
  const Scenario near{"near",
                      Vec2(0.0, 0.0),
                      {Pose2{Vec2(-1.5, 0.0), 0.0}, Pose2{Vec2(-1.5, -1.0), 0.0}},
                      {Pose2{Vec2(0.25, 0.0), kPi}}};
  const MatchTrialResult r = RunTrial(setup_, near, attackers, opponents, 5);
  ASSERT_EQ(r.counters.stuck_penalties, 1);
  const std::vector<double>& t = opponents.times_s[0];
  double longest_gap_s = 0.0, gap_from_s = 0.0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] - t[i - 1] > longest_gap_s) {
      longest_gap_s = t[i] - t[i - 1];
      gap_from_s = t[i - 1];
    }
  }
  EXPECT_NEAR(gap_from_s, sim_.stuck_after_s, 2.0 * sim_.control_step_s);
  EXPECT_NEAR(longest_gap_s, sim_.stuck_penalty_s, 2.0 * sim_.control_step_s);
}

TEST_F(MatchTest, AnOpponentBackFromAPenaltyWalksBackIntoItsRegion) {
  sim_.stuck_penalty_s = 2.0;
  config_.time_limit_s = sim_.stuck_after_s + sim_.stuck_penalty_s + 7.0;
  setup_.trace_period_s = sim_.control_step_s;
  config_.clear_kick = "straight";
  Stand attackers;
  OpponentTeam opponents(config_, field_, kicks_, robot_, sim_);
  // The ball lies just outside the defender's region: it waits at the boundary, facing it.
  const FieldBox& region = config_.opponents[0].region;
  const Scenario outside{"outside",
                         Vec2(region.x_max_m + 0.3, 0.0),
                         {Pose2{Vec2(-1.5, 0.0), 0.0}, Pose2{Vec2(-1.5, -1.0), 0.0}},
                         {Pose2{Vec2(region.x_max_m, 0.0), 0.0}}};
  const MatchTrialResult r = RunTrial(setup_, outside, attackers, opponents, 5);
  ASSERT_EQ(r.counters.stuck_penalties, 1);
  bool left = false;
  for (const TraceFrame& f : r.trace) left = left || !region.Contains(f.robots[2].p_F);
  EXPECT_TRUE(left);  // the penalty placed it outside its region
  EXPECT_TRUE(region.Contains(r.trace.back().robots[2].p_F));
}

TEST_F(MatchTest, NoLocalGameStuckWithNobodyNearTheBall) {
  config_.time_limit_s = 2.0 * sim_.stuck_after_s;
  Stand attackers, opponents;
  // Every body's edge more than stuck_proximity_m from the ball.
  const double far_m = robot_.body_radius_m + sim_.stuck_proximity_m + 0.05;
  const Scenario alone{"alone",
                       Vec2(0.0, 0.0),
                       {Pose2{Vec2(-far_m, 0.0), 0.0}, Pose2{Vec2(-1.5, -1.0), 0.0}},
                       {Pose2{Vec2(far_m, 0.0), kPi}}};
  EXPECT_EQ(RunTrial(setup_, alone, attackers, opponents, 5).counters.stuck_penalties, 0);
}

// A holder that releases the ball leaves it at rest where it held it.
TEST_F(MatchTest, AReleasedBallLiesAtRestInFrontOfTheRobot) {
  GetAndKick attackers(CommandKind::kRelease);
  Stand opponents;
  const MatchTrialResult r = RunTrial(setup_, OneOpponentAhead(-2.0), attackers, opponents, 7);
  Vec2 at(0.0, 0.0);
  int releases = 0;
  for (const MatchEvent& e : r.events) {
    if (e.kind == EventKind::kRelease) {
      ++releases;
      at = e.p_F_ball;
    }
  }
  ASSERT_EQ(releases, 1);
  EXPECT_EQ(r.events.back().p_F_ball, at);
  EXPECT_EQ(r.counters.attacker_kicks[0], 0);
}

}  // namespace
}  // namespace foresight
