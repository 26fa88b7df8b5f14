// The CBR team's protocol (Ros et al. 2009, sec. 4) on a scripted message bus, without the match
// simulator: robots stand where the test puts them, messages arrive one control step later
// (or are dropped), so each rule of cbr/cbr_team.h can be watched in isolation.
#include "cbr/cbr_team.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "cbr/retrieval_params.h"
#include "cbr/team_params.h"
#include "common/error.h"
#include "models/model_paths.h"
#include "tests/cbr/cbr_test_cases.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

constexpr double kDt = 0.04;

// The default behaviour: stands still (or, with `kick`, kicks a ball it holds) and counts how
// often it played.
class StandStill final : public TeamPolicy {
 public:
  RobotCommand Decide(const Perception& p) override {
    ++calls;
    RobotCommand c;
    if (kick && p.holding_ball) c.kind = CommandKind::kKick;
    return c;
  }
  int calls = 0;
  bool kick = false;
};

struct Sent {
  int step = 0;
  TeamMessage message;
};

class CbrTeamTest : public ::testing::Test {
 protected:
  CbrTeamTest()
      : base_(LoadCaseBase(DefaultCaseBasePath(testing::ModelsDir()), testing::ModelsDir())),
        team_params_(LoadCbrTeamParams("team", testing::ModelsDir())),
        retrieval_(LoadRetrievalParams(testing::ModelsDir() / "cbr" / "retrieval.json",
                                       base_.rules.field)) {
    poses_ = {Pose2(Vec2(1.0, 0.2), 0.0), Pose2(Vec2(0.2, -1.0), 0.0)};
    // The race's robots: the AIBO's walk (models/match/aibo_ers7.json) and body + ball radius.
    team_params_.race = RaceParams{0.3, 0.12 + 0.042, kDt};
  }

  CbrTeam& MakeTeam() {
    setup_.cases = &base_.cases;
    setup_.skills.team = &team_params_;
    setup_.skills.retrieval = &retrieval_;
    setup_.skills.kicks = &base_.rules.kicks;
    setup_.skills.aim_tolerance_rad = 10.0 * kDegToRad;
    setup_.skills.release_after_s = 2.7;
    setup_.skills.release_kick = 0;
    setup_.skills.control_step_s = kDt;
    team_.emplace(setup_, fallback_, 2);
    return *team_;
  }

  // Plays `steps` control steps of the robots in `active`.
  void Run(int steps, const std::vector<int>& active = {0, 1}) {
    for (int k = 0; k < steps; ++k, ++step_) {
      std::vector<std::vector<TeamMessage>> inbox(2);
      for (const Sent& s : sent_) {
        if (s.step != step_ - 1) continue;
        for (int r : {0, 1}) {
          if (r != s.message.sender && !(drop && drop(s.message))) {
            inbox[static_cast<std::size_t>(r)].push_back(s.message);
          }
        }
      }
      for (int r : active) {
        Perception p;
        p.time_s = step_ * kDt;
        p.self = r;
        p.pose = poses_[static_cast<std::size_t>(r)];
        p.holding_ball = holding_[static_cast<std::size_t>(r)];
        p.busy = busy_[static_cast<std::size_t>(r)];
        p.p_F_ball = ball_;
        p.teammates = poses_;
        for (const Vec2& o : opponents_) p.opponents.push_back(Pose2(o, kPi));
        p.inbox = inbox[static_cast<std::size_t>(r)];
        RobotCommand c = team_->Decide(p);
        last_[static_cast<std::size_t>(r)] = c;
        if (c.message) {
          c.message->sender = r;
          c.message->sent_time_s = p.time_s;
          sent_.push_back({step_, *c.message});
        }
      }
    }
  }

  // The senders of the messages of `kind`, in order.
  std::vector<int> SendersOf(CbrMessageKind kind) const {
    std::vector<int> senders;
    for (const Sent& s : sent_) {
      if (s.message.kind == static_cast<int>(kind)) senders.push_back(s.message.sender);
    }
    return senders;
  }

  // The team plays a case base of the one case `c`.
  void PlayOnly(const Case& c) {
    one_.emplace(std::vector<Case>{c}, base_.kick_mirrors);
    MakeTeam();
    setup_.cases = &*one_;
    team_.emplace(setup_, fallback_, 2);
  }

  // Puts robot `robot` where its last walk command takes it (a step's command reaches its
  // target in one step).
  void MoveAlongLastWalk(int robot) {
    Pose2& pose = poses_[static_cast<std::size_t>(robot)];
    const RobotCommand& walk = last_[static_cast<std::size_t>(robot)];
    pose.p_F += Vec2(std::cos(pose.theta_rad) * walk.v_R_mps.x() -
                         std::sin(pose.theta_rad) * walk.v_R_mps.y(),
                     std::sin(pose.theta_rad) * walk.v_R_mps.x() +
                         std::cos(pose.theta_rad) * walk.v_R_mps.y()) *
                kDt;
  }

  // Robot 0, at its adapted position, grabs the ball and kicks it at the goal (facing it within
  // the aim tolerance); the ball ends at `after`.
  void GrabAndKick(const Vec2& after) {
    Run(1);
    EXPECT_EQ(team_->PhaseOf(0), CbrPhase::kExecute);
    EXPECT_EQ(last_[0].kind, CommandKind::kGetBall);
    holding_[0] = true;
    Run(1);
    EXPECT_EQ(last_[0].kind, CommandKind::kKick);  // facing the goal within the aim tolerance
    busy_[0] = true;
    Run(5);
    holding_[0] = false;
    busy_[0] = false;
    ball_ = after;
    Run(1);
  }

  double Counter(const std::string& name) const {
    for (const TeamPolicy::Counter& c : team_->Counters()) {
      if (c.name == name) return c.value;
    }
    ADD_FAILURE() << "no counter " << name;
    return -1.0;
  }

  LoadedCaseBase base_;
  CbrTeamParams team_params_;
  RetrievalParams retrieval_;
  CbrTeamSetup setup_;
  StandStill fallback_;
  std::optional<CaseBase> one_;
  std::optional<CbrTeam> team_;
  std::vector<Pose2> poses_;
  Vec2 ball_{1.3, 0.2};
  std::vector<Vec2> opponents_;
  std::vector<Sent> sent_;
  std::function<bool(const TeamMessage&)> drop;
  std::vector<bool> holding_{false, false};
  std::vector<bool> busy_{false, false};
  std::vector<RobotCommand> last_{RobotCommand{}, RobotCommand{}};
  int step_ = 0;
};

TEST_F(CbrTeamTest, LowestIdChoosesTheClosestRobotWhichRetrievesForTheTeam) {
  MakeTeam();
  Run(3);
  EXPECT_EQ(SendersOf(CbrMessageKind::kCoordinator), std::vector<int>{0});
  EXPECT_EQ(SendersOf(CbrMessageKind::kCase), std::vector<int>{0});  // robot 0 is closest
  EXPECT_EQ(Counter("cases_retrieved"), 1.0);
  EXPECT_EQ(team_->CycleOf(0), 1);
  EXPECT_EQ(team_->CycleOf(1), 1);  // robot 1 adopted the case
  EXPECT_NE(team_->PhaseOf(1), CbrPhase::kIdle);
}

TEST_F(CbrTeamTest, TheSelectorNamesATeammateCloserToTheBall) {
  std::swap(poses_[0], poses_[1]);  // robot 1 is now next to the ball
  MakeTeam();
  Run(4);
  EXPECT_EQ(SendersOf(CbrMessageKind::kCoordinator), std::vector<int>{0});
  EXPECT_EQ(SendersOf(CbrMessageKind::kCase), std::vector<int>{1});
  EXPECT_EQ(team_->CycleOf(0), 1);
  EXPECT_EQ(team_->CycleOf(1), 1);
}

TEST_F(CbrTeamTest, OnlyRetrieversCoordinate) {
  std::swap(poses_[0], poses_[1]);
  team_params_.retrievers = 1;
  MakeTeam();
  Run(4);
  EXPECT_EQ(SendersOf(CbrMessageKind::kCase), std::vector<int>{0});
}

TEST_F(CbrTeamTest, ARobotThatLeftIsNoLongerTheSelector) {
  MakeTeam();
  // Robot 0 is gone from the start: robot 1 waits for it while it still counts as present...
  Run(static_cast<int>(0.9 * team_params_.presence_timeout_s / kDt), {1});
  EXPECT_TRUE(SendersOf(CbrMessageKind::kCoordinator).empty());
  // ... and then chooses the coordinator itself: itself, the only retriever present.
  Run(static_cast<int>(0.2 * team_params_.presence_timeout_s / kDt) + 2, {1});
  EXPECT_EQ(SendersOf(CbrMessageKind::kCoordinator), std::vector<int>{1});
  EXPECT_EQ(SendersOf(CbrMessageKind::kCase), std::vector<int>{1});
  EXPECT_NE(team_->PhaseOf(1), CbrPhase::kIdle);
}

TEST_F(CbrTeamTest, AdaptingPastItsTimeoutAborts) {
  poses_[0] = Pose2(Vec2(0.6, 0.6), 0.0);  // far from any adapted position, and frozen there
  MakeTeam();
  Run(3);
  ASSERT_EQ(Counter("cases_retrieved"), 1.0);
  ASSERT_EQ(team_->PhaseOf(0), CbrPhase::kAdapt);
  Run(static_cast<int>(team_params_.adapt_timeout_s / kDt) - 5);
  EXPECT_EQ(Counter("aborts_timeout"), 0.0);
  Run(10);
  EXPECT_EQ(Counter("aborts_timeout"), 1.0);
  EXPECT_EQ(SendersOf(CbrMessageKind::kAbort).size(), 1u);
  // The same situation would time out again: the default behaviour plays while the ball stays in
  // the case's scope, however long, and no new cycle begins...
  const int cycle = team_->CycleOf(0);
  Run(static_cast<int>(3.0 * team_params_.adapt_timeout_s / kDt));
  EXPECT_EQ(team_->CycleOf(0), cycle);
  EXPECT_EQ(Counter("aborts_timeout"), 1.0);
  // ...until the ball has left it.
  ball_ += Vec2(0.0, 1.2);
  Run(3);
  EXPECT_GT(team_->CycleOf(0), cycle);
}

TEST_F(CbrTeamTest, AfterATimeoutTheTeammateHoldsOffTooUntilItHoldsTheBall) {
  poses_[0] = Pose2(Vec2(0.6, 0.6), 0.0);
  MakeTeam();
  Run(3);
  Run(static_cast<int>(team_params_.adapt_timeout_s / kDt) + 5);
  ASSERT_EQ(Counter("aborts_timeout"), 1.0);
  // Robot 0 falls silent: robot 1, which heard the abort, becomes the selector and holds off
  // while the ball stays in the case's scope...
  const int cycle = team_->CycleOf(1);
  Run(static_cast<int>(3.0 * team_params_.presence_timeout_s / kDt), {1});
  EXPECT_EQ(team_->CycleOf(1), cycle);
  // ...until it holds the ball itself.
  holding_[1] = true;
  Run(3, {1});
  EXPECT_GT(team_->CycleOf(1), cycle);
}

TEST_F(CbrTeamTest, ABallThatLeftTheCaseScopeAborts) {
  poses_[0] = Pose2(Vec2(0.6, 0.6), 0.0);
  MakeTeam();
  Run(3);
  ASSERT_EQ(team_->PhaseOf(0), CbrPhase::kAdapt);
  ball_ += Vec2(0.0, 1.2);  // pushed away by someone
  Run(1);
  EXPECT_EQ(Counter("aborts_ball_moved"), 1.0);  // one aborted cycle...
  EXPECT_EQ(SendersOf(CbrMessageKind::kAbort).size(), 2u);  // ...that both robots saw at once
}

TEST_F(CbrTeamTest, AnOpponentOnTheBallAbortsAndNoCycleStartsUntilItIsFree) {
  poses_[0] = Pose2(Vec2(0.6, 0.6), 0.0);
  MakeTeam();
  Run(3);
  ASSERT_EQ(team_->PhaseOf(0), CbrPhase::kAdapt);
  opponents_ = {ball_ + Vec2(retrieval_.opponent_radius_m + retrieval_.ball_radius_m, 0.0)};
  Run(1);
  EXPECT_EQ(Counter("aborts_ball_lost"), 1.0);
  const int cycle = team_->CycleOf(0);
  const int played = fallback_.calls;
  Run(50);
  EXPECT_EQ(team_->CycleOf(0), cycle);  // the default behaviour fights for the ball
  EXPECT_GT(fallback_.calls, played);
  opponents_.clear();
  Run(3);
  EXPECT_EQ(team_->CycleOf(0), cycle + 1);
}

TEST_F(CbrTeamTest, NoCycleStartsWhileAnOpponentWinsTheRaceOrTheBallRolls) {
  // Robot 0 is 0.5 m from the ball (1.3, 0.2), robot 1 farther; an opponent 0.3 m from it, not
  // touching it but 0.2 m (0.67 s) nearer than robot 0: the default behaviour plays.
  poses_[0] = Pose2(Vec2(0.8, 0.2), 0.0);
  opponents_ = {ball_ + Vec2(0.0, 0.3)};
  MakeTeam();
  Run(20);
  EXPECT_TRUE(SendersOf(CbrMessageKind::kCoordinator).empty());
  EXPECT_EQ(team_->CycleOf(0), 0);
  // Without the race the paper's team starts a cycle at once.
  team_params_.ball_race = false;
  sent_.clear();
  MakeTeam();
  Run(3);
  EXPECT_EQ(SendersOf(CbrMessageKind::kCoordinator), std::vector<int>{0});
  // With it, once the opponent steps back the team wins, but not while the ball rolls.
  team_params_.ball_race = true;
  sent_.clear();
  MakeTeam();
  opponents_[0] = ball_ + Vec2(0.0, 1.0);
  for (int k = 0; k < 10; ++k) {
    ball_ += Vec2(0.02, 0.0);  // 0.5 m/s, faster than the robots walk
    Run(1);
  }
  EXPECT_TRUE(SendersOf(CbrMessageKind::kCoordinator).empty());
  Run(3);  // the ball rests
  EXPECT_EQ(SendersOf(CbrMessageKind::kCoordinator), std::vector<int>{0});
}

TEST_F(CbrTeamTest, NoCycleStartsWhileATeammateKicksTheBallAway) {
  // Robot 1 holds the ball and kicks it in the default behaviour before any cycle: it tells at
  // once, so the selector (robot 0) does not retrieve for a ball that is about to leave.
  team_params_.ball_race = false;
  poses_[1] = Pose2(ball_ - Vec2(0.16, 0.0), 0.0);
  holding_[1] = true;
  fallback_.kick = true;
  MakeTeam();
  Run(1, {1});
  ASSERT_EQ(last_[1].kind, CommandKind::kKick);
  ASSERT_TRUE(last_[1].message);
  EXPECT_EQ(last_[1].message->words[kKickingWord], 1);
  holding_[1] = false;
  busy_[1] = true;
  Run(10);  // the kick motion, 0.4 s
  EXPECT_TRUE(SendersOf(CbrMessageKind::kCoordinator).empty());
  busy_[1] = false;
  ball_ += Vec2(1.0, 0.0);
  Run(10);  // free again: its next report says so, and a cycle starts
  EXPECT_EQ(SendersOf(CbrMessageKind::kCoordinator), std::vector<int>{0});
}

TEST_F(CbrTeamTest, ACoordinatorNamedDuringItsOwnKickRetrievesNothing) {
  // The selector (robot 0) has not heard that robot 1 kicks (its kicking reports are lost) and
  // names it coordinator: robot 1 retrieves nothing for the ball it kicks away; once the kick
  // is over it retrieves.
  team_params_.ball_race = false;
  poses_[1] = Pose2(ball_ - Vec2(0.16, 0.0), 0.0);
  holding_[1] = true;
  drop = [](const TeamMessage& m) { return m.sender == 1 && m.words[kKickingWord] == 1; };
  MakeTeam();
  Run(1, {1});  // robot 1 reports its distance, not kicking yet
  fallback_.kick = true;
  Run(1);  // robot 0 names robot 1; robot 1 starts its kick
  ASSERT_EQ(SendersOf(CbrMessageKind::kCoordinator), std::vector<int>{0});
  ASSERT_EQ(last_[1].kind, CommandKind::kKick);
  holding_[1] = false;
  busy_[1] = true;
  fallback_.kick = false;
  Run(10);
  EXPECT_TRUE(SendersOf(CbrMessageKind::kCase).empty());
  EXPECT_TRUE(SendersOf(CbrMessageKind::kNoCase).empty());
  busy_[1] = false;
  Run(40);  // the wait for the case times out, robot 1 is free: a new cycle retrieves
  EXPECT_FALSE(SendersOf(CbrMessageKind::kCase).empty() &&
               SendersOf(CbrMessageKind::kNoCase).empty());
}

TEST_F(CbrTeamTest, ARobotAwaitingTheCaseKeepsTheBallItHolds) {
  // One retriever (robot 0) retrieves; robot 1 holds the ball and waits for the case, which is
  // lost: it keeps the ball rather than kick it away in the default behaviour, until the wait
  // times out.
  team_params_.ball_race = false;
  team_params_.retrievers = 1;
  poses_[1] = Pose2(ball_ - Vec2(0.16, 0.0), 0.0);
  holding_[1] = true;
  drop = [](const TeamMessage& m) { return m.kind == static_cast<int>(CbrMessageKind::kCase); };
  MakeTeam();
  for (int k = 0; k < 10 && team_->PhaseOf(1) != CbrPhase::kAwaitCase; ++k) Run(1);
  ASSERT_EQ(team_->PhaseOf(1), CbrPhase::kAwaitCase);
  fallback_.kick = true;
  Run(1);
  EXPECT_EQ(team_->PhaseOf(1), CbrPhase::kAwaitCase);
  EXPECT_EQ(last_[1].kind, CommandKind::kStand);
  Run(static_cast<int>(team_params_.await_case_timeout_s / kDt) + 1);
  EXPECT_EQ(last_[1].kind, CommandKind::kKick);  // no case came: the default behaviour plays
}

TEST_F(CbrTeamTest, TheRaceWithoutTheRobotsSpeedIsRefused) {
  team_params_.race = RaceParams{};
  EXPECT_THROW(MakeTeam(), InputError);
  team_params_.ball_race = false;  // the paper's team needs no speed
  EXPECT_NO_THROW(MakeTeam());
}

TEST_F(CbrTeamTest, TheKickRacePassesOverACaseAnOpponentBreaksBeforeItsFirstKick) {
  // Robot 0 is 0.3 m behind the ball, an opponent 0.35 m beside it: robot 0 wins the ball race
  // (0.46 s against 0.63 s) but no case kicks the ball away within 0.63 s (the grab and the
  // launch alone take 0.6 s after the 0.46 s walk).
  poses_[0] = Pose2(ball_ + Vec2(-0.3, 0.0), 0.0);
  opponents_ = {ball_ + Vec2(0.0, -0.35)};
  team_params_.hold = HoldParams{0.3, 0.15, 45.0 * kDegToRad, 2.4, 0.3};
  team_params_.kick_race = false;
  MakeTeam();
  Run(5);
  ASSERT_FALSE(SendersOf(CbrMessageKind::kCase).empty());  // without it a case is reused
  team_params_.kick_race = true;
  sent_.clear();
  MakeTeam();
  Run(5);
  EXPECT_TRUE(SendersOf(CbrMessageKind::kCase).empty());
  EXPECT_GT(Counter("kick_race_lost"), 0.0);
  EXPECT_EQ(SendersOf(CbrMessageKind::kNoCase), std::vector<int>{0});
}

// Robot 0 holds the ball facing +y; its case kicks it up the field. The retrieval's corridor
// starts at the ball and passes the opponent; the kick's starts where the ball will leave once
// the robot has turned, and meets it: "path blocked". The same ball would retrieve the same case
// again and block it again; the coordinator passes over it until the ball has left its scope.
TEST_F(CbrTeamTest, ACaseGivenUpForABlockedPathIsNotRetrievedAgainForTheSameBall) {
  ball_ = Vec2(0.0, 0.16);
  poses_[0] = Pose2(Vec2(0.0, 0.0), 0.5 * kPi);
  poses_[1] = Pose2(Vec2(-1.5, -1.0), 0.0);
  holding_[0] = true;
  opponents_ = {Vec2(0.45, -0.08)};
  PlayOnly(testing::GetAndKickCase("kick_up", ball_, Vec2(0.0, 0.0), "forward", Vec2(2.0, 0.16)));
  Run(20);
  // The case and its mirror image (kicking 0.32 m further right) are each tried once...
  const double tried = Counter("cases_retrieved");
  ASSERT_GE(tried, 1.0);
  ASSERT_LE(tried, 2.0);
  EXPECT_EQ(Counter("aborts_path_blocked"), tried);
  Run(50);
  EXPECT_EQ(Counter("cases_retrieved"), tried);  // ...and not retrieved and blocked again:
  EXPECT_GT(Counter("blocked_skipped"), 0.0);
  EXPECT_FALSE(SendersOf(CbrMessageKind::kNoCase).empty());  // the default behaviour plays
  // Once the ball has left the case's scope around where it was retrieved, the case is back.
  holding_[0] = false;
  ball_ = Vec2(0.0, 1.0);
  Run(3);
  ball_ = Vec2(0.0, 0.16);
  holding_[0] = true;
  Run(20);
  EXPECT_GT(Counter("cases_retrieved"), tried);
}

TEST_F(CbrTeamTest, TheKickRaceWithoutTheRobotsTimesIsRefused) {
  team_params_.kick_race = true;
  team_params_.hold = HoldParams{};
  EXPECT_THROW(MakeTeam(), InputError);
  team_params_.hold = HoldParams{0.3, 0.15, 45.0 * kDegToRad, 2.4, 0.3};
  EXPECT_NO_THROW(MakeTeam());
}

TEST_F(CbrTeamTest, ARobotWhoseMessagesAreAllLostDoesNotStallTheOther) {
  drop = [](const TeamMessage& m) { return m.sender == 0; };
  std::swap(poses_[0], poses_[1]);  // robot 1 is closest: robot 0 would name it, but is unheard
  MakeTeam();
  Run(static_cast<int>(2.0 * team_params_.presence_timeout_s / kDt));
  // Robot 1 stops counting robot 0 as present, becomes the selector and plays its own cycles.
  const std::vector<int> coordinators = SendersOf(CbrMessageKind::kCoordinator);
  EXPECT_NE(std::find(coordinators.begin(), coordinators.end(), 1), coordinators.end());
  EXPECT_NE(team_->PhaseOf(1), CbrPhase::kIdle);
  EXPECT_NE(team_->PhaseOf(1), CbrPhase::kAwaitCase);
}

TEST_F(CbrTeamTest, MessagesOfAnOlderCycleAreIgnored) {
  poses_[0] = Pose2(Vec2(0.6, 0.6), 0.0);
  MakeTeam();
  Run(6);
  ASSERT_EQ(team_->CycleOf(1), 1);
  const TeamMessage old_abort = MakeCbrMessage(CbrMessageKind::kAbort, 0, ball_, 0.0, 0);
  sent_.push_back({step_ - 1, old_abort});
  sent_.back().message.sender = 0;
  const CbrPhase before = team_->PhaseOf(1);
  Run(1);
  EXPECT_EQ(team_->PhaseOf(1), before);
  EXPECT_EQ(team_->CycleOf(1), 1);
}

// One individual case through every state of Fig. 10: ADAPT until robot 0 stands at its adapted
// position, EXECUTE (get the ball, aim, kick), WAIT END until the coordinator has heard everyone,
// END, and a new cycle.
TEST_F(CbrTeamTest, AnIndividualCaseRunsThroughEveryState) {
  poses_[1] = Pose2(Vec2(-2.0, -1.5), 0.0);  // far away: the case is robot 0's alone
  // Turned against the calibrated forward kick's mean direction (issue 12: 6.5 deg to the left on
  // Tekkotsu's legs), so that kicking from where the case sends it faces the goal within the aim
  // tolerance without a turn on the spot.
  const KickModel& kicks = base_.rules.kicks;
  const auto forward = static_cast<std::size_t>(*kicks.Find("forward"));
  const double forward_rad = kicks.kicks[forward].direction_rad;
  poses_[0] = Pose2(Vec2(0.7, 0.45), -forward_rad);
  // A case base of one case whose gameplay is known: get the ball, kick it at the goal.
  Case c;
  c.name = "kick_at_goal";
  c.source = c.name;
  c.p_F_ball = Vec2(1.3, 0.2);
  c.ball_scope = {0.6, 0.5};
  CaseAction get, kick;
  get.type = ActionType::kGetBall;
  kick.type = ActionType::kKick;
  kick.kick = "forward";
  kick.at_goal = true;
  c.teammates = {{1, Vec2(1.0, 0.2), {get, kick}}};
  PlayOnly(c);
  Run(4);
  ASSERT_EQ(Counter("cases_individual"), 1.0);
  ASSERT_EQ(team_->PhaseOf(0), CbrPhase::kAdapt);
  EXPECT_EQ(team_->PhaseOf(1), CbrPhase::kWaitEnd);  // not in the case
  EXPECT_EQ(last_[0].kind, CommandKind::kWalk);       // walking to its adapted position
  MoveAlongLastWalk(0);
  GrabAndKick(Vec2(2.2, 0.1));
  EXPECT_EQ(team_->PhaseOf(0), CbrPhase::kIdle);  // done, and the coordinator ended the cycle
  EXPECT_EQ(SendersOf(CbrMessageKind::kDone), std::vector<int>{0});
  Run(10);
  EXPECT_EQ(SendersOf(CbrMessageKind::kEnd), std::vector<int>{0});  // one message a step
  EXPECT_GE(team_->CycleOf(1), 2);  // everyone is in the next cycle
  EXPECT_EQ(Counter("aborts_timeout") + Counter("aborts_ball_lost") + Counter("aborts_ball_moved") +
                Counter("aborts_path_blocked"),
            0.0);
}

// Sec. 4.2: "The execution of the case continues until all robots finish their sequences of
// actions". Robot 0 gets the ball and kicks it; robot 1 walks far away meanwhile: robot 0 waits
// for it past the wait-end timeout, no new cycle supersedes the case, and the coordinator ends
// it once robot 1 is there.
TEST_F(CbrTeamTest, ARobotThatFinishedWaitsForItsTeammateToFinish) {
  const KickModel& kicks = base_.rules.kicks;
  const auto forward = static_cast<std::size_t>(*kicks.Find("forward"));
  poses_[0] = Pose2(Vec2(0.7, 0.45), -kicks.kicks[forward].direction_rad);
  Case c;
  c.name = "kick_while_the_other_walks";
  c.source = c.name;
  c.p_F_ball = Vec2(1.3, 0.2);
  c.ball_scope = {0.6, 0.5};
  CaseAction get, kick, walk;
  get.type = ActionType::kGetBall;
  kick.type = ActionType::kKick;
  kick.kick = "forward";
  kick.at_goal = true;
  walk.type = ActionType::kGoTo;
  walk.target_F = Vec2(-1.0, -1.0);
  c.teammates = {{1, Vec2(1.0, 0.2), {get, kick}}, {2, poses_[1].p_F, {walk}}};
  PlayOnly(c);
  Run(4);
  ASSERT_EQ(Counter("cases_cooperative"), 1.0);
  MoveAlongLastWalk(0);
  GrabAndKick(Vec2(2.2, 0.1));
  ASSERT_EQ(team_->PhaseOf(0), CbrPhase::kWaitEnd);
  EXPECT_EQ(team_->PhaseOf(1), CbrPhase::kExecute);
  const int waited = static_cast<int>(std::ceil(2.0 * team_params_.wait_end_timeout_s / kDt));
  Run(waited);
  EXPECT_EQ(team_->PhaseOf(0), CbrPhase::kWaitEnd);  // still waiting: the case is not over
  EXPECT_EQ(team_->PhaseOf(1), CbrPhase::kExecute);
  EXPECT_EQ(SendersOf(CbrMessageKind::kCoordinator).size(), 1u);  // no new cycle began
  EXPECT_EQ(Counter("cases_completed"), 0.0);
  poses_[1].p_F = *walk.target_F;  // robot 1 is there: its sequence ends
  Run(10);
  EXPECT_EQ(SendersOf(CbrMessageKind::kEnd).size(), 1u);
  EXPECT_EQ(Counter("cases_completed"), 1.0);
  EXPECT_EQ(Counter("cases_multi_kick"), 0.0);  // one kick between them
  EXPECT_EQ(Counter("wait_end_timeouts"), 0.0);
}

TEST(TeamMessagesTest, CorrespondencePacksAndUnpacks) {
  const CaseRobots robots{1, 0, -1, 3};
  EXPECT_EQ(UnpackRobots(PackRobots(robots)), robots);
}

}  // namespace
}  // namespace foresight
