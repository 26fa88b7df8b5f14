// Algorithms 1 and 2 (sec. 3.4): the ranking agrees with the paper's lists sorted one criterion at
// a time; hand-made problems retrieve, reject and rank as the paper describes, with explanations.
#include "cbr/retrieval.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/random.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

// The paper's procedure written out naively: four band lists each sorted by cost, concatenated,
// then stably sorted by teammates, then stably by conditions (the most significant last), for
// the default order; for other orders the same idea with the criteria applied last-first.
std::vector<int> NaiveRanking(const std::vector<CaseEvaluation>& candidates,
                              const RetrievalParams& params) {
  std::vector<int> list(candidates.size());
  for (std::size_t i = 0; i < list.size(); ++i) list[i] = static_cast<int>(i);
  const auto at = [&](int i) -> const CaseEvaluation& {
    return candidates[static_cast<std::size_t>(i)];
  };
  std::stable_sort(list.begin(), list.end(),
                   [&](int a, int b) { return at(a).case_index < at(b).case_index; });
  for (int k = 2; k >= 0; --k) {
    switch (params.order[static_cast<std::size_t>(k)]) {
      case RankCriterion::kBandThenCost: {
        std::vector<int> bands[4];
        for (int i : list) bands[SimilarityBand(at(i).ball_similarity, params)].push_back(i);
        list.clear();
        for (auto& band : bands) {
          std::stable_sort(band.begin(), band.end(), [&](int a, int b) {
            return at(a).correspondence.cost < at(b).correspondence.cost;
          });
          list.insert(list.end(), band.begin(), band.end());
        }
        break;
      }
      case RankCriterion::kTeammates:
        std::stable_sort(list.begin(), list.end(),
                         [&](int a, int b) { return at(a).teammates > at(b).teammates; });
        break;
      case RankCriterion::kConditions:
        std::stable_sort(list.begin(), list.end(),
                         [&](int a, int b) { return at(a).conditions > at(b).conditions; });
        break;
    }
  }
  return list;
}

TEST(RetrievalTest, RankingAgreesWithTheNaiveSortOnRandomCandidates) {
  RandomStream rng(StreamKey(13, 1));
  const std::array<std::array<RankCriterion, 3>, 3> orders{{
      {RankCriterion::kConditions, RankCriterion::kTeammates, RankCriterion::kBandThenCost},
      {RankCriterion::kTeammates, RankCriterion::kConditions, RankCriterion::kBandThenCost},
      {RankCriterion::kBandThenCost, RankCriterion::kConditions, RankCriterion::kTeammates},
  }};
  for (int trial = 0; trial < 300; ++trial) {
    RetrievalParams params;
    params.order = orders[static_cast<std::size_t>(trial % 3)];
    params.cost = trial % 2 == 0 ? CostFunction::kSum : CostFunction::kMaxThenSum;
    const int n = 1 + static_cast<int>(rng.NextBits() % 40);
    std::vector<CaseEvaluation> candidates;
    for (int i = 0; i < n; ++i) {
      CaseEvaluation e;
      e.case_index = i;
      e.verdict = Verdict::kCandidate;
      e.conditions = static_cast<int>(rng.NextBits() % 3);
      e.teammates = 1 + static_cast<int>(rng.NextBits() % 4);
      // Coarse values so that ties in every criterion happen.
      e.ball_similarity = 0.37 + 0.63 * std::round(rng.NextUniform() * 8.0) / 8.0;
      e.band = SimilarityBand(e.ball_similarity, params);
      const double sum = std::round(rng.NextUniform() * 6.0) / 2.0;
      const double max = std::round(rng.NextUniform() * 3.0) / 2.0;
      e.correspondence.cost = MakeCostKey(params.cost, sum, max);
      candidates.push_back(e);
    }
    std::vector<int> sorted(candidates.size());
    for (std::size_t i = 0; i < sorted.size(); ++i) sorted[i] = static_cast<int>(i);
    std::sort(sorted.begin(), sorted.end(), [&](int a, int b) {
      return RanksBefore(candidates[static_cast<std::size_t>(a)],
                         candidates[static_cast<std::size_t>(b)], params);
    });
    ASSERT_EQ(sorted, NaiveRanking(candidates, params)) << "trial " << trial;
  }
}

TEST(RetrievalTest, BandsFollowThePapersIntervals) {
  const RetrievalParams params;
  EXPECT_EQ(SimilarityBand(1.0, params), 0);
  EXPECT_EQ(SimilarityBand(0.8, params), 0);
  EXPECT_EQ(SimilarityBand(0.7999, params), 1);
  EXPECT_EQ(SimilarityBand(0.6, params), 1);
  EXPECT_EQ(SimilarityBand(0.4, params), 2);
  EXPECT_EQ(SimilarityBand(0.3999, params), 3);
}

CaseAction Act(ActionType type) {
  CaseAction a;
  a.type = type;
  a.kick = "forward";
  return a;
}

// One robot behind the ball shoots at the goal.
Case Solo(const std::string& name) {
  Case c;
  c.name = name;
  c.p_F_ball = Vec2(0.0, 0.0);
  c.ball_scope = {0.6, 0.6};
  CaseAction shoot = Act(ActionType::kKick);
  shoot.at_goal = true;
  c.teammates.push_back({1, {-0.2, 0.0}, {Act(ActionType::kGetBall), shoot}});
  return c;
}

// Teammate 1 passes to teammate 2 at (1.0, 0.8) relative to the ball, who shoots.
Case Pass(const std::string& name) {
  Case c = Solo(name);
  CaseAction pass = Act(ActionType::kPass);
  pass.teammate = 2;
  CaseAction receive = Act(ActionType::kReceive);
  receive.teammate = 1;
  CaseAction shoot = Act(ActionType::kKick);
  shoot.at_goal = true;
  c.teammates[0].actions = {Act(ActionType::kGetBall), pass};
  c.teammates.push_back({2, {1.0, 0.8}, {receive, shoot}});
  return c;
}

Problem TwoRobots() {
  Problem p;
  p.p_F_ball = Vec2(0.1, 0.1);
  p.teammates = {{3, Pose2{{-0.3, 0.2}, 0.0}}, {4, Pose2{{1.2, 1.0}, 0.0}}};
  return p;
}

TEST(RetrievalTest, AnOpenPathRetrievesThePassCase) {
  const std::vector<Case> cases{Solo("solo"), Pass("pass")};
  Problem p = TwoRobots();
  p.opponents = {Vec2(-1.5, -1.0)};  // far away
  const RetrievalParams params;
  const RetrievalResult r = Retrieve(cases, p, params);
  ASSERT_TRUE(r.retrieved.has_value());
  EXPECT_EQ(*r.retrieved, 1);  // more teammates
  EXPECT_EQ(r.ranking, (std::vector<int>{1, 0}));
  const CaseEvaluation& best = *r.Best();
  EXPECT_EQ(best.rank, 0);
  EXPECT_EQ(r.evaluations[0].rank, 1);
  EXPECT_EQ(best.correspondence.problem_index[0], 0);  // robot 3 takes the ball
  EXPECT_EQ(best.correspondence.problem_index[1], 1);  // robot 4 receives
  EXPECT_TRUE(best.correspondence.adapted_F[1].isApprox(Vec2(1.1, 0.9)));
  ASSERT_EQ(r.ball_path.count, 2);
  EXPECT_TRUE(r.ball_path.trajectories[0].end_F.isApprox(Vec2(1.1, 0.9)));
  EXPECT_THAT(Explain(best, cases[1], p, params), HasSubstr("candidate, rank 0"));
}

TEST(RetrievalTest, AnOpponentInThePassCorridorRejectsItAndIsNamed) {
  const std::vector<Case> cases{Solo("solo"), Pass("pass")};
  Problem p = TwoRobots();
  p.opponents = {Vec2(-1.5, -1.0), Vec2(0.6, 0.5)};  // opponent 1 halfway along the pass
  const RetrievalParams params;
  const RetrievalResult r = Retrieve(cases, p, params);
  ASSERT_TRUE(r.retrieved.has_value());
  EXPECT_EQ(*r.retrieved, 0);  // the solo shot along y = 0.1 passes the opponent
  const CaseEvaluation& pass = r.evaluations[1];
  EXPECT_EQ(pass.verdict, Verdict::kPathBlocked);
  EXPECT_EQ(pass.path.opponent, 1);
  EXPECT_EQ(pass.path.trajectory, 0);
  EXPECT_EQ(pass.rank, -1);
  const std::string why = Explain(pass, cases[1], p, params);
  EXPECT_THAT(why, HasSubstr("path blocked: opponent 1 at (0.6, 0.5) on trajectory 0"));
  EXPECT_THAT(why, HasSubstr("pass by teammate 1 to teammate 2"));
}

TEST(RetrievalTest, AnOpponentOnTheShotAfterThePassBlocksTheSecondTrajectory) {
  // Fig. 8a: the ball path is the pass t0 and then the receiver's shot t1 from (1.1, 0.9) to the
  // goal centre (2.7, 0); the opponent stands on t1, 0.8 m along it.
  const std::vector<Case> cases{Pass("pass")};
  Problem p = TwoRobots();
  const Vec2 from(1.1, 0.9), to(2.7, 0.0);
  p.opponents = {from + 0.8 * (to - from).normalized()};
  const RetrievalParams params;
  const RetrievalResult r = Retrieve(cases, p, params);
  EXPECT_FALSE(r.retrieved.has_value());
  EXPECT_EQ(r.evaluations[0].verdict, Verdict::kPathBlocked);
  EXPECT_EQ(r.evaluations[0].path.trajectory, 1);
  EXPECT_DOUBLE_EQ(r.evaluations[0].path.membership, 1.0);
  EXPECT_THAT(Explain(r.evaluations[0], cases[0], p, params),
              HasSubstr("on trajectory 1 (kick by teammate 2 from (1.1, 0.9) to (2.7, 0))"));
  // Defending yellow, the same case mirrored in x shoots at -x: the opponent is no longer there.
  Case mirrored = Pass("pass_yellow");
  mirrored.defending = DefendingGoal::kYellow;
  Problem q = p;
  q.defending = DefendingGoal::kYellow;
  EXPECT_TRUE(Retrieve(std::vector<Case>{mirrored}, q, params).retrieved.has_value());
}

TEST(RetrievalTest, AnOpponentInACasesScopeRaisesItAboveAnEqualCase) {
  Case plain = Solo("plain");
  Case guarded = Solo("guarded");
  guarded.opponents.push_back({1, {0.5, -0.6}, {0.3, 0.3}});  // front right of the ball
  const std::vector<Case> cases{plain, guarded};
  Problem p = TwoRobots();
  const RetrievalParams params;
  // Without opponents: a tie on every criterion, the lower index wins.
  EXPECT_EQ(Retrieve(cases, p, params).retrieved, 0);
  // An opponent in the moved scope (0.6, -0.5) and off the shot's corridor.
  p.opponents = {Vec2(0.65, -0.45)};
  const RetrievalResult r = Retrieve(cases, p, params);
  EXPECT_EQ(r.retrieved, 1);
  EXPECT_EQ(r.evaluations[1].conditions, 1);
  EXPECT_EQ(r.evaluations[0].conditions, 0);
}

TEST(RetrievalTest, RejectionsExplainThemselves) {
  Case far_ball = Solo("far_ball");
  far_ball.p_F_ball = Vec2(2.0, 0.0);
  Case far_robot = Pass("far_robot");
  far_robot.teammates[1].p_F = Vec2(-2.0, -1.2);  // adapted (-1.9, -1.1): 2.6 m and more away
  Case three = Pass("three");
  three.teammates.push_back({3, {0.0, -1.0}, {Act(ActionType::kWait)}});
  Case yellow = Solo("yellow");
  yellow.defending = DefendingGoal::kYellow;
  const std::vector<Case> cases{far_ball, far_robot, three, yellow};
  const Problem p = TwoRobots();
  const RetrievalParams params;
  const RetrievalResult r = Retrieve(cases, p, params);
  EXPECT_FALSE(r.retrieved.has_value());  // "no case" is a result
  EXPECT_TRUE(r.ranking.empty());
  EXPECT_EQ(r.evaluations[0].verdict, Verdict::kBallOutOfScope);
  EXPECT_THAT(Explain(r.evaluations[0], cases[0], p, params),
              HasSubstr("ball out of scope: similarity "));
  EXPECT_NEAR(r.evaluations[0].ball_similarity, std::exp(-(1.9 * 1.9 + 0.1 * 0.1) / 0.36), 1e-12);
  EXPECT_EQ(r.evaluations[1].verdict, Verdict::kTooFar);
  const double far = (Vec2(-0.3, 0.2) - Vec2(-1.9, -1.1)).norm();
  EXPECT_NEAR(r.evaluations[1].correspondence.far_distance_m, far, 1e-12);
  EXPECT_THAT(Explain(r.evaluations[1], cases[1], p, params),
              HasSubstr("too far: robot 3 would walk 2.062 m to case teammate 2's adapted "
                        "position (-1.9, -1.1) > thr_c 1.5 m"));
  EXPECT_EQ(r.evaluations[2].verdict, Verdict::kTooFewTeammates);
  EXPECT_THAT(Explain(r.evaluations[2], cases[2], p, params),
              HasSubstr("the case needs 3, the problem has 2"));
  EXPECT_EQ(r.evaluations[3].verdict, Verdict::kOtherGoal);
  EXPECT_THAT(Explain(r.evaluations[3], cases[3], p, params), HasSubstr("other defending goal"));
}

TEST(RetrievalTest, ACandidatesExplanationGivesItsMeasures) {
  const std::vector<Case> cases{Solo("solo")};
  Problem p = TwoRobots();
  p.p_F_ball = Vec2(0.3, 0.3);  // sim = exp(-(0.09 + 0.09) / 0.36) = exp(-0.5) ~ 0.607: band h
  const RetrievalParams params;
  const RetrievalResult r = Retrieve(cases, p, params);
  ASSERT_EQ(r.retrieved, 0);
  EXPECT_NEAR(r.Best()->ball_similarity, std::exp(-0.5), 1e-12);
  EXPECT_EQ(r.Best()->band, 1);
  // Robot 3 at (-0.3, 0.2) walks to the adapted (0.1, 0.3).
  EXPECT_THAT(Explain(*r.Best(), cases[0], p, params),
              HasSubstr("candidate, rank 0: conditions 0, teammates 1, similarity 0.607 (band h), "
                        "cost 0.412 m (sum)"));
  // Five teammates: the problem is rejected for every case, with a reason.
  p.teammates.resize(5, p.teammates.front());
  const RetrievalResult bad = Retrieve(cases, p, params);
  EXPECT_FALSE(bad.retrieved.has_value());
  EXPECT_EQ(bad.evaluations[0].verdict, Verdict::kInvalidProblem);
}

}  // namespace
}  // namespace foresight
