// The timing-aware pass check (cbr/pass_timing.h): it sees what the free-path test of the paper
// cannot (an opponent outside the corridor fast enough to step in; a slow one inside it that
// the ball passes first), and its estimate falls as an opponent comes closer.
#include "cbr/pass_timing.h"

#include <gtest/gtest.h>

#include <cmath>

namespace foresight {
namespace {

class PassTimingTest : public ::testing::Test {
 protected:
  PassTimingTest() {
    kicks_.robot = "aibo_ers7";
    kicks_.rolling_deceleration_mps2 = 0.27;
    kicks_.kicks = {{"forward", 1.2, 0.05, 0.0, 0.05}};
    pass_.type = ActionType::kPass;
    pass_.kick = "forward";
    params_.reaction_s = 0.5;
    params_.opponent_speed_mps = 0.3;
    params_.receiver_speed_mps = 0.3;
    params_.reach_m = 0.162;
    params_.time_step_s = 0.02;
    DrawPassSamples(30, &params_);
    RetrievalParams retrieval;
    retrieval.widths = TrajectoryWidths::kData;
    path_.count = 1;
    path_.trajectories[0] = MakeTrajectory(Vec2(0.0, 0.0), Vec2(2.0, 0.0), {"forward"}, retrieval);
    path_.trajectories[0].action = ActionType::kPass;
    path_.trajectories[0].kick = &pass_;
  }
  double Success(const std::vector<Vec2>& opponents) const {
    return PassSuccess(path_, opponents, kicks_, params_);
  }
  bool FreePath(const std::vector<Vec2>& opponents) const {
    return CheckFreePath(path_, opponents, std::exp(-1.0)).free;
  }

  KickModel kicks_;
  CaseAction pass_;
  PassTimingParams params_;
  CaseBallPath path_;
};

TEST_F(PassTimingTest, NoOpponentNoRisk) {
  EXPECT_EQ(Success({}), 1.0);
}

TEST_F(PassTimingTest, AnOpponentOnTheLineStopsEveryPass) {
  EXPECT_EQ(Success({Vec2(1.0, 0.0)}), 0.0);
}

TEST_F(PassTimingTest, AFastOpponentOutsideTheCorridorIntercepts) {
  // 0.45 m off the line at 0.5 m: outside the paper's corridor (r 0.1-0.3 m), so the free-path
  // test lets the pass through; a robot that reacts at once and walks 1 m/s gets there first.
  const std::vector<Vec2> opponent = {Vec2(0.5, 0.45)};
  EXPECT_TRUE(FreePath(opponent));
  params_.reaction_s = 0.0;
  params_.opponent_speed_mps = 1.0;
  EXPECT_LT(Success(opponent), 0.1);
}

TEST_F(PassTimingTest, ASlowOpponentInsideTheCorridorIsPassedFirst) {
  // 0.2 m off the line near the end of the pass: inside the corridor, so the paper's test
  // rejects the pass; at 3 cm/s it needs far longer to step in than the ball needs to pass.
  const std::vector<Vec2> opponent = {Vec2(1.7, 0.25)};
  EXPECT_FALSE(FreePath(opponent));
  params_.opponent_speed_mps = 0.03;
  const double slow = Success(opponent);
  // Only the kicks whose direction error (sigma 0.05 rad) sends the ball into its body fail.
  EXPECT_GT(slow, 0.7);
  params_.opponent_speed_mps = 0.3;
  EXPECT_LT(Success(opponent), slow);
}

TEST_F(PassTimingTest, SuccessFallsAsTheOpponentComesCloser) {
  double last = 1.0;
  for (double y : {1.5, 0.9, 0.6, 0.4, 0.25}) {
    const double s = Success({Vec2(1.2, y)});
    EXPECT_LE(s, last) << "opponent at y = " << y;
    last = s;
  }
  EXPECT_LT(last, 0.5);
  EXPECT_EQ(Success({Vec2(1.2, 3.0)}), 1.0);
}

TEST_F(PassTimingTest, OnlyPassesAreJudged) {
  path_.trajectories[0].action = ActionType::kKick;  // a shot: the receiver is the goal
  EXPECT_EQ(Success({Vec2(1.0, 0.0)}), 1.0);
}

}  // namespace
}  // namespace foresight
