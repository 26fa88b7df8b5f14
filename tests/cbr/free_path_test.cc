// Fuzzy trajectories and the ball path (sec. 3.3.1, Fig. 7, 8a).
#include "cbr/free_path.h"

#include <gtest/gtest.h>

#include <cmath>

namespace foresight {
namespace {

const double kEdge = std::exp(-1.0);

// Fig. 7b: r_min 0.1 m, r_max 0.3 m, l 0.5 m, from the origin along +x.
FuzzyTrajectory Figure7(const Vec2& start = Vec2(0.0, 0.0), double heading = 0.0) {
  RetrievalParams params;
  KickTrajectory kick{"k", 0.1, 0.3, 0.0, 0.0};
  return MakeTrajectory(start, start + 0.5 * UnitVector(heading), kick, params);
}

TEST(FreePathTest, Figure7MembershipByHand) {
  const FuzzyTrajectory t = Figure7();
  EXPECT_DOUBLE_EQ(TrajectoryMembership(t, Vec2(0.0, 0.0)), 1.0);
  EXPECT_DOUBLE_EQ(TrajectoryMembership(t, Vec2(0.3, 0.0)), 1.0);
  // x' = 0.25: rho = 0.1 + 0.2 * 0.5 = 0.2; y' = 0.1: exp(-(0.5)^2).
  EXPECT_NEAR(TrajectoryMembership(t, Vec2(0.25, 0.1)), std::exp(-0.25), 1e-12);
  EXPECT_NEAR(TrajectoryMembership(t, Vec2(0.25, -0.1)), std::exp(-0.25), 1e-12);
  // x' = 0: rho = 0.1, y' = 0.1: the edge.
  EXPECT_NEAR(TrajectoryMembership(t, Vec2(0.0, 0.1)), kEdge, 1e-12);
  // x' = 0.5: rho = 0.3; y' = 0.3 the edge, y' = 0.6: exp(-4).
  EXPECT_NEAR(TrajectoryMembership(t, Vec2(0.5, 0.3)), kEdge, 1e-12);
  EXPECT_NEAR(TrajectoryMembership(t, Vec2(0.5, 0.6)), std::exp(-4.0), 1e-12);
  // Behind the start and past the end: nothing.
  EXPECT_EQ(TrajectoryMembership(t, Vec2(-0.001, 0.0)), 0.0);
  EXPECT_EQ(TrajectoryMembership(t, Vec2(0.501, 0.0)), 0.0);
}

TEST(FreePathTest, MembershipIsInTheTrajectorysOwnFrame) {
  // The same trajectory turned by 120 degrees and moved: the same values at the moved points.
  const double h = 120.0 * kDegToRad;
  const Vec2 s(1.0, -0.7);
  const FuzzyTrajectory t = Figure7(s, h);
  const Pose2 frame{s, h};
  EXPECT_NEAR(TrajectoryMembership(t, frame.ToField(Vec2(0.25, 0.1))), std::exp(-0.25), 1e-12);
  EXPECT_NEAR(TrajectoryMembership(t, frame.ToField(Vec2(0.5, -0.3))), kEdge, 1e-12);
  EXPECT_EQ(TrajectoryMembership(t, frame.ToField(Vec2(-0.01, 0.0))), 0.0);
}

TEST(FreePathTest, JustInsideAndJustOutsideTheEdgeBlockOrNot) {
  CaseBallPath path;
  path.trajectories[0] = Figure7();
  path.count = 1;
  // x' = 0.25, rho = 0.2.
  const std::vector<Vec2> inside{{3.0, 3.0}, {0.25, 0.2 * 0.999}};
  const std::vector<Vec2> outside{{0.25, 0.2 * 1.001}, {0.25, -0.2 * 1.001}};
  const PathCheck blocked = CheckFreePath(path, inside, kEdge);
  EXPECT_FALSE(blocked.free);
  EXPECT_EQ(blocked.opponent, 1);
  EXPECT_EQ(blocked.trajectory, 0);
  EXPECT_GT(blocked.membership, kEdge);
  EXPECT_TRUE(CheckFreePath(path, outside, kEdge).free);
}

TEST(FreePathTest, KickModelWidthsGrowWithTheDirectionNoise) {
  RetrievalParams params;
  params.widths = TrajectoryWidths::kKickModel;
  params.opponent_radius_m = 0.12;
  params.ball_radius_m = 0.042;
  params.width_sigmas = 2.0;
  const KickTrajectory kick{"forward", 0.1, 0.3, 0.0, 5.0 * kDegToRad};
  const FuzzyTrajectory t = MakeTrajectory(Vec2(0, 0), Vec2(2.0, 0), kick, params);
  EXPECT_NEAR(t.r_start_m, 0.162, 1e-12);
  EXPECT_NEAR(t.r_end_m, 0.162 + 2.0 * std::tan(10.0 * kDegToRad), 1e-12);
  // A kick without a direction noise keeps its data widths.
  const FuzzyTrajectory d =
      MakeTrajectory(Vec2(0, 0), Vec2(2.0, 0), KickTrajectory{"x", 0.1, 0.3, 0.0, 0.0}, params);
  EXPECT_DOUBLE_EQ(d.r_end_m, 0.3);
}

CaseAction Act(ActionType type) {
  CaseAction a;
  a.type = type;
  a.kick = "forward";
  return a;
}

// Teammate 1 behind the ball passes to teammate 2, who goes to a spot first, receives and
// shoots at the goal.
Case PassThenShoot(DefendingGoal goal) {
  Case c;
  c.defending = goal;
  c.p_F_ball = Vec2(0.0, 0.0);
  CaseAction pass = Act(ActionType::kPass);
  pass.teammate = 2;
  CaseAction go = Act(ActionType::kGoTo);
  go.target_F = Vec2(1.0, 0.8);
  CaseAction receive = Act(ActionType::kReceive);
  receive.teammate = 1;
  CaseAction shoot = Act(ActionType::kKick);
  shoot.at_goal = true;
  c.teammates.push_back({1, {-0.2, 0.0}, {Act(ActionType::kGetBall), pass}});
  c.teammates.push_back({2, {1.0, 0.5}, {go, receive, shoot}});
  return c;
}

TEST(FreePathTest, BallPathFollowsTheGameplayAndMovesTargetsWithTheBall) {
  Problem p;
  p.p_F_ball = Vec2(0.5, -0.2);
  const RetrievalParams params;
  for (DefendingGoal goal : {DefendingGoal::kCyan, DefendingGoal::kYellow}) {
    const Case c = PassThenShoot(goal);
    const std::vector<Vec2> adapted{Vec2(0.3, -0.2), Vec2(1.5, 0.3)};
    const CaseBallPath path = BuildBallPath(p, c, adapted, params);
    ASSERT_EQ(path.count, 2);
    // The pass goes to where the receiver waits: its go_to target, moved with the ball.
    EXPECT_TRUE(path.trajectories[0].start_F.isApprox(Vec2(0.5, -0.2)));
    EXPECT_TRUE(path.trajectories[0].end_F.isApprox(Vec2(1.5, 0.6)));
    EXPECT_EQ(path.trajectories[0].action, ActionType::kPass);
    EXPECT_EQ(path.trajectories[0].kicker, 0);
    EXPECT_EQ(path.trajectories[0].receiver, 1);
    // Then the shot from there to the attacked goal's centre.
    EXPECT_TRUE(path.trajectories[1].start_F.isApprox(Vec2(1.5, 0.6)));
    EXPECT_TRUE(path.trajectories[1].end_F.isApprox(Vec2(AttackSign(goal) * 2.7, 0.0)));
    EXPECT_EQ(path.trajectories[1].kicker, 1);
  }
}

TEST(FreePathTest, ReachCutsATrajectoryAndTheNextStartsWhereItEnds) {
  Problem p;
  p.p_F_ball = Vec2(0.0, 0.0);
  Case c;
  c.p_F_ball = Vec2(0.0, 0.0);
  CaseAction kick = Act(ActionType::kKick);
  kick.target_F = Vec2(2.0, 0.0);
  CaseAction again = Act(ActionType::kKick);
  again.target_F = Vec2(2.0, 1.0);
  c.teammates.push_back({1, {-0.2, 0.0}, {Act(ActionType::kGetBall), kick, again}});
  RetrievalParams params;
  params.kicks.push_back({"forward", 0.1, 0.3, 1.5, 0.0, 1.3});  // reach 1.5 m, mean roll 1.3 m
  const std::vector<Vec2> adapted{Vec2(-0.2, 0.0)};
  const CaseBallPath path = BuildBallPath(p, c, adapted, params);
  ASSERT_EQ(path.count, 2);
  EXPECT_NEAR(path.trajectories[0].length_m, 1.5, 1e-12);
  EXPECT_TRUE(path.trajectories[1].start_F.isApprox(Vec2(1.5, 0.0)));
  // 1.12 m to the target, within reach: the kick rolls on, its corridor runs to its mean roll.
  EXPECT_NEAR(path.trajectories[1].length_m, 1.3, 1e-12);
  EXPECT_TRUE(path.trajectories[1].end_F.isApprox(Vec2(1.5, 0.0) +
                                                  1.3 / std::sqrt(1.25) * Vec2(0.5, 1.0)));
}

TEST(FreePathTest, AKickShortOfItsMeanRollRunsOnToItAndTheGameplayGoesOnFromItsTarget) {
  Problem p;
  p.p_F_ball = Vec2(0.0, 0.0);
  Case c;
  c.p_F_ball = Vec2(0.0, 0.0);
  CaseAction kick = Act(ActionType::kKick);
  kick.target_F = Vec2(1.0, 0.0);
  CaseAction shoot = Act(ActionType::kKick);
  shoot.at_goal = true;
  c.teammates.push_back({1, {-0.2, 0.0}, {Act(ActionType::kGetBall), kick, shoot}});
  RetrievalParams params;
  params.kicks.push_back({"forward", 0.1, 0.3, 3.0, 0.0, 2.5});  // reach 3 m, mean roll 2.5 m
  const std::vector<Vec2> adapted{Vec2(-0.2, 0.0)};
  const CaseBallPath path = BuildBallPath(p, c, adapted, params);
  ASSERT_EQ(path.count, 2);
  const FuzzyTrajectory& t = path.trajectories[0];
  // The corridor ends where the ball stops on average, not at the reach of a launch 2 sd strong:
  // an opponent 2.8 m out, beyond the mean roll, does not block the kick.
  EXPECT_TRUE(t.end_F.isApprox(Vec2(2.5, 0.0)));
  EXPECT_TRUE(CheckFreePath(path, std::vector<Vec2>{Vec2(2.8, 0.0)}, params.thr_trajectory).free);
  EXPECT_TRUE(t.aim_F.isApprox(Vec2(1.0, 0.0)));  // the robot aims at the target
  EXPECT_NEAR(t.knee_m, 1.0, 1e-12);
  // An opponent 2 m out, past the target but inside the kick's roll, blocks it; the width there
  // is r_max (0.3 m) ...
  EXPECT_FALSE(CheckFreePath(path, std::vector<Vec2>{Vec2(2.0, 0.05)}, params.thr_trajectory).free);
  EXPECT_NEAR(TrajectoryExponent(t, Vec2(2.0, 0.3)), 1.0, 1e-12);
  // ... and before the target the corridor is the one to the target: 0.2 m half-width halfway,
  // not the 0.14 m of a trapezoid stretched to 2.5 m.
  EXPECT_NEAR(TrajectoryExponent(t, Vec2(0.5, 0.2)), 1.0, 1e-12);
  EXPECT_FALSE(CheckFreePath(path, std::vector<Vec2>{Vec2(0.5, 0.19)}, params.thr_trajectory).free);
  EXPECT_TRUE(path.trajectories[1].start_F.isApprox(Vec2(1.0, 0.0)));
  // Without a reach the trajectory ends at the target, as the paper draws it.
  params.kicks.clear();
  const CaseBallPath paper = BuildBallPath(p, c, adapted, params);
  EXPECT_TRUE(paper.trajectories[0].end_F.isApprox(Vec2(1.0, 0.0)));
}

TEST(FreePathTest, AShotAtAGoalLineTargetIsNotRunOn) {
  Problem p;
  p.p_F_ball = Vec2(0.0, 0.0);
  Case c;
  c.p_F_ball = Vec2(0.0, 0.0);
  CaseAction kick = Act(ActionType::kKick);
  kick.target_F = Vec2(2.7, 0.0);  // on the goal line (goal_x_m 2.7): a shot
  c.teammates.push_back({1, {-0.2, 0.0}, {Act(ActionType::kGetBall), kick}});
  RetrievalParams params;
  params.kicks.push_back({"forward", 0.1, 0.3, 4.0, 0.0, 3.0});  // reach 4 m, mean roll 3 m
  const std::vector<Vec2> adapted{Vec2(-0.2, 0.0)};
  const FuzzyTrajectory t = BuildBallPath(p, c, adapted, params).trajectories[0];
  EXPECT_NEAR(t.length_m, 2.7, 1e-12);
  EXPECT_EQ(t.knee_m, 0.0);
  // The same kick at a target 0.1 m short of the line runs on to its 3 m mean roll.
  c.teammates[0].actions[1].target_F = Vec2(2.6, 0.0);
  EXPECT_NEAR(BuildBallPath(p, c, adapted, params).trajectories[0].length_m, 3.0, 1e-12);
}

}  // namespace
}  // namespace foresight
