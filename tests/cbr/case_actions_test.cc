// One robot's actions (cbr/case_actions.h): a pass with a head kick is aimed so that the kick's
// own direction (about 89 deg to the side) points at the receiver; the kick goes once aimed; a
// blocked trajectory aborts; a receiver waits until the pass is heard or seen.
#include "cbr/case_actions.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cbr/case_base.h"
#include "cbr/team_params.h"
#include "tests/cbr/cbr_test_cases.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

constexpr double kDt = 0.04;

class CaseActionsTest : public ::testing::Test {
 protected:
  CaseActionsTest()
      : base_(LoadCaseBase(DefaultCaseBasePath(testing::ModelsDir()), testing::ModelsDir())),
        team_(LoadCbrTeamParams("team", testing::ModelsDir())) {
    ctx_.team = &team_;
    ctx_.retrieval = &retrieval_;
    ctx_.kicks = &base_.rules.kicks;
    ctx_.aim_tolerance_rad = 10.0 * kDegToRad;
    ctx_.release_after_s = 2.7;
    ctx_.control_step_s = kDt;
    // Robot 0 passes with the left head kick to robot 1, 1 m to its left.
    CaseAction get, pass, receive;
    get.type = ActionType::kGetBall;
    pass.type = ActionType::kPass;
    pass.kick = "head_kick_left";
    pass.teammate = 2;
    receive.type = ActionType::kReceive;
    receive.teammate = 1;
    c_.name = c_.source = "pass_left";
    c_.p_F_ball = Vec2(0.0, 0.0);
    c_.ball_scope = {0.5, 0.5};
    c_.teammates = {{1, Vec2(-0.2, 0.0), {get, pass}}, {2, Vec2(0.0, 1.0), {receive}}};
    play_ = MakeCasePlay(c_, 0, 1, Vec2(0.0, 0.0), {0, 1, -1, -1}, retrieval_);
  }

  Perception Holding(double theta_rad) const {
    Perception p;
    p.time_s = 1.0;
    p.self = 0;
    p.pose = Pose2(Vec2(-0.16, 0.0), theta_rad);
    p.holding_ball = true;
    p.p_F_ball = Vec2(0.0, 0.0);
    p.teammates = {p.pose, Pose2(Vec2(0.0, 1.0), 0.0)};
    return p;
  }

  LoadedCaseBase base_;
  CbrTeamParams team_;
  RetrievalParams retrieval_;
  ActionContext ctx_;
  Case c_;
  CasePlay play_;
};

TEST_F(CaseActionsTest, AHeadKickPassTurnsTheKicksDirectionOntoTheReceiver) {
  const KickSpec& head = base_.rules.kicks.kicks[*base_.rules.kicks.Find("head_kick_left")];
  ActionProgress progress;
  progress.action = 1;  // holding the ball: the pass
  progress.holding_since_s = 1.0;
  progress.was_holding = true;
  // Facing the receiver (+90 deg) is wrong for a kick that leaves 89 deg to the left: the robot
  // must turn until heading + direction points at the receiver, i.e. to about 1 deg.
  const ActionStep turn = StepActions(play_, 0, progress, Holding(0.5 * kPi), ctx_);
  ASSERT_FALSE(turn.abort);
  EXPECT_EQ(turn.command.kind, CommandKind::kWalk);
  const double wanted = 0.5 * kPi - head.direction_rad;
  EXPECT_NEAR(turn.command.turn_radps * kDt, WrapAngle(wanted - 0.5 * kPi), 1e-9);
  // Aimed within the tolerance: it kicks the head kick.
  const ActionStep kick = StepActions(play_, 0, progress, Holding(wanted + 0.05), ctx_);
  EXPECT_EQ(kick.command.kind, CommandKind::kKick);
  EXPECT_EQ(kick.command.kick_index, *base_.rules.kicks.Find("head_kick_left"));
}

TEST_F(CaseActionsTest, AnOpponentOnThePassLineAbortsThePass) {
  ActionProgress progress;
  progress.action = 1;
  Perception p = Holding(0.0);
  p.opponents = {Pose2(Vec2(0.0, 0.5), 0.0)};  // halfway to the receiver
  EXPECT_EQ(StepActions(play_, 0, progress, p, ctx_).abort, AbortReason::kPathBlocked);
  p.opponents = {Pose2(Vec2(0.0, -0.8), 0.0)};  // behind the passer's kick: free
  EXPECT_FALSE(StepActions(play_, 0, progress, p, ctx_).abort);
}

// The free-path test at the kick is on the corridor the ball will take: from where it leaves once
// the robot has turned to aim (the held ball turns with it at its front), not from where the turn
// has it now. A robot facing +y holds the ball at its left; an opponent beside that ball's line
// to the target, clear of the line from the launch point, does not abort the kick.
TEST_F(CaseActionsTest, TheKickChecksThePathFromWhereTheBallWillLeave) {
  const Case c = testing::GetAndKickCase("kick_on", Vec2(0.0, 0.0), Vec2(-0.3, 0.0), "forward",
                                         Vec2(2.0, 0.0));
  const CasePlay play = MakeCasePlay(c, 0, 1, Vec2(0.0, 0.0), {0, -1, -1, -1}, retrieval_);
  Perception p;
  p.time_s = 1.0;
  p.self = 0;
  p.pose = Pose2(Vec2(0.0, 0.0), 0.5 * kPi);
  p.holding_ball = true;
  p.p_F_ball = Vec2(0.0, 0.16);  // at its front, to the left of the line the kick will take
  p.teammates = {p.pose};
  p.opponents = {Pose2(Vec2(0.5, 0.24), 0.0)};
  ActionProgress progress;
  progress.action = 1;
  progress.holding_since_s = 1.0;
  progress.was_holding = true;
  const ActionStep turn = StepActions(play, 0, progress, p, ctx_);
  EXPECT_FALSE(turn.abort);
  EXPECT_EQ(turn.command.kind, CommandKind::kWalk);  // turning to aim
  // On the kick's own line the same opponent blocks it.
  p.opponents = {Pose2(Vec2(0.5, 0.0), 0.0)};
  EXPECT_EQ(StepActions(play, 0, progress, p, ctx_).abort, AbortReason::kPathBlocked);
}

TEST_F(CaseActionsTest, TheReceiverWaitsForThePassHeardOrSeen) {
  Perception p;
  p.time_s = 1.0;
  p.self = 1;
  p.pose = Pose2(Vec2(0.0, 1.0), -0.5 * kPi);
  p.p_F_ball = Vec2(0.0, 0.0);
  p.teammates = {Pose2(Vec2(-0.16, 0.0), 0.0), p.pose};
  ActionProgress progress;
  EXPECT_EQ(StepActions(play_, 1, progress, p, ctx_).command.kind, CommandKind::kWalk);  // waits
  ++progress.passes_heard;
  EXPECT_EQ(StepActions(play_, 1, progress, p, ctx_).command.kind, CommandKind::kGetBall);
  // The message lost: the ball seen leaving the passer after it had it starts the receive too.
  ActionProgress unheard;
  StepActions(play_, 1, unheard, p, ctx_);  // the ball at the passer
  p.p_F_ball = Vec2(0.0, 0.5);
  EXPECT_EQ(StepActions(play_, 1, unheard, p, ctx_).command.kind, CommandKind::kGetBall);
}

// Under dependent positioning a receiver executes before it reaches its adapted position; until
// the pass it walks on to that position (where the pass goes), facing the ball, and there only
// turns. After an action of its own that moved it (a go_to), it waits where it is.
TEST_F(CaseActionsTest, TheReceiverWalksOnToItsSpotUntilThePass) {
  Perception p;
  p.time_s = 1.0;
  p.self = 1;
  p.pose = Pose2(Vec2(0.4, 0.3), -0.5 * kPi);  // 0.81 m short of its spot (0, 1)
  p.p_F_ball = Vec2(0.0, 0.0);
  p.teammates = {Pose2(Vec2(-0.16, 0.0), 0.0), p.pose};
  ActionProgress progress;
  const RobotCommand walk = StepActions(play_, 1, progress, p, ctx_).command;
  ASSERT_EQ(walk.kind, CommandKind::kWalk);
  const Vec2 v_F = p.pose.ToField(walk.v_R_mps) - p.pose.p_F;  // the velocity turned into F
  EXPECT_GT(v_F.dot((Vec2(0.0, 1.0) - p.pose.p_F).normalized()), 0.9 * v_F.norm());
  EXPECT_GT(v_F.norm(), 0.0);
  p.pose = Pose2(Vec2(0.0, 1.0), -0.4 * kPi);  // at its spot: it turns to the ball, no step
  const RobotCommand turn = StepActions(play_, 1, progress, p, ctx_).command;
  EXPECT_EQ(turn.v_R_mps.norm(), 0.0);
  EXPECT_LT(turn.turn_radps, 0.0);

  Case moved = c_;
  CaseAction go_to;
  go_to.type = ActionType::kGoTo;
  go_to.target_F = Vec2(0.4, 0.3);
  moved.teammates[1].actions.insert(moved.teammates[1].actions.begin(), go_to);
  const CasePlay play = MakeCasePlay(moved, 0, 1, Vec2(0.0, 0.0), {0, 1, -1, -1}, retrieval_);
  p.pose = Pose2(Vec2(0.4, 0.3), -0.5 * kPi);
  ActionProgress after_go_to;
  after_go_to.action = 1;
  EXPECT_EQ(StepActions(play, 1, after_go_to, p, ctx_).command.v_R_mps.norm(), 0.0);
}

// A receiver that adopted the case only after the pass left (its messages lost) never saw the
// passer with the ball: the ball gone from both the passer and where the case found it starts
// its receive; still at the case's ball, it waits.
TEST_F(CaseActionsTest, AReceiverThatCameLateSeesThePassFromWhereTheBallWent) {
  Perception p;
  p.time_s = 1.0;
  p.self = 1;
  p.pose = Pose2(Vec2(0.0, 1.0), -0.5 * kPi);
  p.teammates = {Pose2(Vec2(-0.6, 0.0), 0.0), p.pose};  // the passer walked off after its kick
  p.p_F_ball = Vec2(0.05, 0.0);  // still at the case's ball
  ActionProgress late;
  EXPECT_EQ(StepActions(play_, 1, late, p, ctx_).command.kind, CommandKind::kWalk);  // waits
  p.p_F_ball = Vec2(0.0, 0.5);  // on its way to the receiver
  EXPECT_EQ(StepActions(play_, 1, late, p, ctx_).command.kind, CommandKind::kGetBall);
}

// A dribble ends once the holding time left is what turning the ball to the next kick's aim
// takes (at dribble_turn_radps) plus a control step, so the kick is aimed, not forced.
TEST_F(CaseActionsTest, ADribbleEndsInTimeToAimTheKickAfterIt) {
  CaseAction get, dribble, kick;
  get.type = ActionType::kGetBall;
  dribble.type = ActionType::kDribble;
  dribble.target_F = Vec2(0.0, 2.0);  // far: never reached in the test
  kick.type = ActionType::kKick;
  kick.kick = "forward";
  kick.at_goal = true;
  Case c = c_;
  c.name = c.source = "dribble_then_shoot";
  c.teammates = {{1, Vec2(-0.2, 0.0), {get, dribble, kick}}};
  const CasePlay play = MakeCasePlay(c, 0, 1, Vec2(0.0, 0.0), {0, -1, -1, -1}, retrieval_);
  ctx_.dribble_turn_radps = 45.0 * kDegToRad;
  // Facing +y, the goal straight along +x: a quarter turn, 2 s at 45 deg/s; with the step,
  // the dribble may last 2.7 - 2.04 = 0.66 s.
  const auto step_after = [&](double held_s) {
    ActionProgress progress;
    progress.action = 1;
    progress.was_holding = true;
    Perception p = Holding(0.5 * kPi);
    progress.holding_since_s = p.time_s - held_s;
    StepActions(play, 0, progress, p, ctx_);
    return progress.action;
  };
  EXPECT_EQ(step_after(0.60), 1u);  // still dribbling
  EXPECT_EQ(step_after(0.70), 2u);  // on to the kick, which turns to aim
  ctx_.dribble_turn_radps = 0.0;    // without the rule the dribble runs to the holding limit
  EXPECT_EQ(step_after(0.70), 1u);
}

}  // namespace
}  // namespace foresight
