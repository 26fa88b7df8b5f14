// The ball race (cbr/ball_race.h): exact times, the tie of one step, the fastest teammate.
#include "cbr/ball_race.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace foresight {
namespace {

const RaceParams kRace{0.3, 0.162, 0.04};

Problem RaceProblem(const std::vector<Vec2>& team, const std::vector<Vec2>& opponents) {
  Problem p;
  p.p_F_ball = Vec2(0.5, 0.25);
  for (std::size_t i = 0; i < team.size(); ++i) {
    p.teammates.push_back({static_cast<int>(i) + 1, Pose2{p.p_F_ball + team[i], 0.0}});
  }
  for (const Vec2& o : opponents) p.opponents.push_back(p.p_F_ball + o);
  return p;
}

TEST(BallRaceTest, TimesAreTheWalkToTouchingTheBall) {
  const BallRace r = RunBallRace(RaceProblem({{-1.0, 0.0}, {0.0, -0.5}}, {{0.0, 2.0}}), kRace);
  EXPECT_EQ(r.fastest, 1);
  EXPECT_NEAR(r.team_s, (0.5 - 0.162) / 0.3, 1e-12);
  EXPECT_NEAR(r.opponents_s, (2.0 - 0.162) / 0.3, 1e-12);
  EXPECT_TRUE(r.won);
}

TEST(BallRaceTest, EachTeammateAgainstTheFastestOpponent) {
  const Problem p = RaceProblem({{-0.3, 0.0}, {1.5, 0.0}}, {{0.0, 0.8}});
  const BallRace r = RunBallRace(p, kRace);
  EXPECT_TRUE(r.won);
  EXPECT_TRUE(TeammateWins(p, 0, r, kRace));   // 0.3 m against 0.8 m
  EXPECT_FALSE(TeammateWins(p, 1, r, kRace));  // 1.5 m: the opponent is there 2.3 s earlier
  EXPECT_NEAR(TimeToBall(p.teammates[1].pose.p_F, p.p_F_ball, kRace), (1.5 - 0.162) / 0.3,
              1e-12);
}

TEST(BallRaceTest, ARobotTouchingTheBallNeedsNoTime) {
  const BallRace r = RunBallRace(RaceProblem({{-0.1, 0.0}}, {{0.15, 0.0}}), kRace);
  EXPECT_EQ(r.team_s, 0.0);
  EXPECT_EQ(r.opponents_s, 0.0);
  EXPECT_TRUE(r.won);  // a tie goes to the team
}

TEST(BallRaceTest, AnOpponentMoreThanOneStepAheadWins) {
  // The opponent 0.35 m from the ball; the teammate a step's walk (0.012 m) and a bit farther.
  const double step_m = kRace.tie_s * kRace.speed_mps;
  const BallRace tie = RunBallRace(RaceProblem({{-0.35 - 0.9 * step_m, 0.0}}, {{0.35, 0.0}}), kRace);
  EXPECT_TRUE(tie.won);
  const BallRace lost =
      RunBallRace(RaceProblem({{-0.35 - 1.1 * step_m, 0.0}}, {{0.35, 0.0}}), kRace);
  EXPECT_FALSE(lost.won);
  EXPECT_NEAR(lost.team_s - lost.opponents_s, 1.1 * kRace.tie_s, 1e-9);
}

TEST(BallRaceTest, WithoutOpponentsTheTeamWinsAndWithoutTeammatesItLoses) {
  const BallRace alone = RunBallRace(RaceProblem({{3.0, 1.0}}, {}), kRace);
  EXPECT_TRUE(alone.won);
  EXPECT_TRUE(std::isinf(alone.opponents_s));
  const BallRace nobody = RunBallRace(RaceProblem({}, {{1.0, 0.0}}), kRace);
  EXPECT_EQ(nobody.fastest, -1);
  EXPECT_FALSE(nobody.won);
}

}  // namespace
}  // namespace foresight
