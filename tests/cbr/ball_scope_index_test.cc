// The ball-scope index (sec. 2.4): a query is a superset of the cases that pass the ball filter,
// and retrieval with the index gives the same retrieved case, ranking, ball path and
// evaluations as without it, on the shipped case base and on a synthetic one of 5,000 cases;
// the cases it skipped are explained on request.
#include "cbr/ball_scope_index.h"

#include <gtest/gtest.h>

#include <cstring>

#include "cbr/case_base.h"
#include "cbr/retrieval.h"
#include "cbr/similarity.h"
#include "cbr/synthetic_cases.h"
#include "common/error.h"
#include "tests/cbr/cbr_random_problems.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

void ExpectSameEvaluation(const CaseEvaluation& a, const CaseEvaluation& b) {
  EXPECT_EQ(a.case_index, b.case_index);
  EXPECT_EQ(a.verdict, b.verdict);
  EXPECT_EQ(std::memcmp(&a.ball_similarity, &b.ball_similarity, sizeof(double)), 0);
  EXPECT_EQ(a.teammates, b.teammates);
  EXPECT_EQ(a.conditions, b.conditions);
  EXPECT_EQ(a.band, b.band);
  EXPECT_EQ(a.rank, b.rank);
  EXPECT_EQ(a.correspondence.feasible, b.correspondence.feasible);
  EXPECT_EQ(a.correspondence.problem_index, b.correspondence.problem_index);
  EXPECT_EQ(std::memcmp(&a.correspondence.cost, &b.correspondence.cost, sizeof(CostKey)), 0);
  EXPECT_EQ(a.path.free, b.path.free);
  EXPECT_EQ(a.path.opponent, b.path.opponent);
  EXPECT_EQ(a.path.trajectory, b.path.trajectory);
}

// Retrieves `trials` random problems with and without the index; returns how many retrieved.
int CompareOnRandomProblems(std::span<const Case> cases, DefendingGoal goal, int trials,
                            std::uint64_t seed) {
  const RetrievalParams params;
  const BallScopeIndex index(cases, params.thr_ball);
  RandomStream rng(StreamKey(seed, 1));
  RetrievalResult full, fast;
  int retrieved = 0;
  for (int t = 0; t < trials; ++t) {
    const Problem p = testing::RandomProblem(rng, goal, 1 + t % 4, t % 4);
    Retrieve(cases, p, params, &full);
    Retrieve(cases, index, p, params, &fast);
    EXPECT_TRUE(full.all_cases);
    EXPECT_FALSE(fast.all_cases);
    EXPECT_EQ(fast.retrieved, full.retrieved) << "trial " << t;
    EXPECT_EQ(fast.ranking, full.ranking) << "trial " << t;
    EXPECT_EQ(fast.ball_path.count, full.ball_path.count);
    for (int k = 0; k < std::min(fast.ball_path.count, full.ball_path.count); ++k) {
      EXPECT_EQ(fast.ball_path.trajectories[k].end_F, full.ball_path.trajectories[k].end_F);
    }
    retrieved += full.retrieved ? 1 : 0;
    for (const CaseEvaluation& e : fast.evaluations) {
      ExpectSameEvaluation(e, full.evaluations[static_cast<std::size_t>(e.case_index)]);
    }
    // Every case the index skipped is out of scope, and EvaluationOf explains it as full does.
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (fast.Find(static_cast<int>(i)) != nullptr) continue;
      const CaseEvaluation& e = full.evaluations[i];
      EXPECT_EQ(e.verdict, Verdict::kBallOutOfScope) << "trial " << t << " case " << i;
      ExpectSameEvaluation(EvaluationOf(fast, cases, p, params, static_cast<int>(i)), e);
    }
    if (fast.retrieved) {
      EXPECT_EQ(fast.Best()->rank, 0);
    }
  }
  return retrieved;
}

LoadedCaseBase Shipped() {
  return LoadCaseBase(DefaultCaseBasePath(testing::ModelsDir()), testing::ModelsDir());
}

TEST(BallScopeIndexTest, RetrievalWithTheIndexEqualsRetrievalWithoutOnTheShippedCases) {
  const LoadedCaseBase base = Shipped();
  for (DefendingGoal goal : {DefendingGoal::kCyan, DefendingGoal::kYellow}) {
    const int retrieved = CompareOnRandomProblems(base.cases.Defending(goal), goal, 2000, 7);
    EXPECT_GT(retrieved, 200);  // the comparison covers real retrievals
  }
}

TEST(BallScopeIndexTest, RetrievalWithTheIndexEqualsRetrievalWithoutOnSyntheticCases) {
  const LoadedCaseBase base = Shipped();
  SyntheticCaseSpec spec;
  spec.count = 5000;
  const std::vector<Case> cases =
      SyntheticCases(base.cases.Defending(DefendingGoal::kCyan), base.kick_mirrors, spec);
  EXPECT_GT(CompareOnRandomProblems(cases, DefendingGoal::kCyan, 300, 8), 100);
  // Small scopes (as bench/cbr_bench.cc's scaled case bases): cells of a few centimetres.
  spec.scope_scale = std::sqrt(68.0 / spec.count);
  const std::vector<Case> small =
      SyntheticCases(base.cases.Defending(DefendingGoal::kCyan), base.kick_mirrors, spec);
  CompareOnRandomProblems(small, DefendingGoal::kCyan, 300, 10);
}

TEST(BallScopeIndexTest, AQueryHoldsEveryCaseWhoseScopeContainsTheBall) {
  const LoadedCaseBase base = Shipped();
  const auto cases = base.cases.Defending(DefendingGoal::kCyan);
  for (double thr : {std::exp(-1.0), 0.1, 0.9}) {
    const BallScopeIndex index(cases, thr);
    RandomStream rng(StreamKey(9, 2));
    for (int t = 0; t < 5000; ++t) {
      Problem p;
      // Also balls off the field and on the boxes' edges (an exact scope edge point).
      const double x = -3.5 + 7.0 * rng.NextUniform();  // x, then y: one draw per statement
      p.p_F_ball = Vec2(x, -2.5 + 5.0 * rng.NextUniform());
      if (t % 5 == 0) {
        const Case& c = cases[static_cast<std::size_t>(t) % cases.size()];
        p.p_F_ball = c.p_F_ball + Vec2(c.ball_scope.tau_x_m * std::sqrt(-std::log(thr)), 0.0);
      }
      const auto hits = index.Query(p.p_F_ball);
      EXPECT_TRUE(std::is_sorted(hits.begin(), hits.end()));
      for (std::size_t i = 0; i < cases.size(); ++i) {
        if (BallSimilarity(p, cases[i]) > thr) {
          EXPECT_TRUE(std::binary_search(hits.begin(), hits.end(), static_cast<std::uint32_t>(i)))
              << "case " << i << " at thr " << thr;
        }
      }
    }
  }
}

TEST(BallScopeIndexTest, AFewHugeScopesCoarsenTheCellsInsteadOfFillingThem) {
  const LoadedCaseBase base = Shipped();
  SyntheticCaseSpec spec;
  spec.count = 2000;
  spec.scope_scale = 0.05;
  std::vector<Case> cases =
      SyntheticCases(base.cases.Defending(DefendingGoal::kCyan), base.kick_mirrors, spec);
  for (std::size_t i = 0; i < cases.size(); i += 100) cases[i].ball_scope = {30.0, 30.0};
  const BallScopeIndex index(cases, std::exp(-1.0));
  EXPECT_LE(index.entries(), 16u * cases.size() + 4096u);
  RandomStream rng(StreamKey(9, 3));
  for (int t = 0; t < 2000; ++t) {
    Problem p;
    p.p_F_ball = Vec2(-2.7 + 5.4 * rng.NextUniform(), 0.0);
    p.p_F_ball.y() = -1.8 + 3.6 * rng.NextUniform();
    const auto hits = index.Query(p.p_F_ball);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (BallSimilarity(p, cases[i]) > std::exp(-1.0)) {
        EXPECT_TRUE(std::binary_search(hits.begin(), hits.end(), static_cast<std::uint32_t>(i)));
      }
    }
  }
}

TEST(BallScopeIndexTest, AnIndexForOtherCasesOrThresholdsIsRefused) {
  const LoadedCaseBase base = Shipped();
  const auto cases = base.cases.Defending(DefendingGoal::kCyan);
  const BallScopeIndex index(cases, 0.5);
  Problem p;
  p.teammates = {{1, Pose2{{0.0, 0.0}, 0.0}}};
  EXPECT_THROW(Retrieve(cases, index, p, RetrievalParams{}), InputError);
  EXPECT_THROW(
      Retrieve(cases.first(3), BallScopeIndex(cases, std::exp(-1.0)), p, RetrievalParams{}),
      InputError);
  EXPECT_THROW(BallScopeIndex(cases, 1.0), InputError);
  const BallScopeIndex empty(std::span<const Case>{}, 0.5);
  EXPECT_TRUE(empty.Query(Vec2(0.0, 0.0)).empty());
}

}  // namespace
}  // namespace foresight
