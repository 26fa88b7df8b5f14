// The correspondence problem (sec. 3.2): adapted positions move with the ball (Fig. 5), the
// trapezoid of Fig. 6 separates sum from max, and the enumeration agrees with brute force.
#include "cbr/correspondence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

#include "common/random.h"

namespace foresight {
namespace {

Problem ProblemWith(const std::vector<Vec2>& robots, const Vec2& ball) {
  Problem p;
  p.p_F_ball = ball;
  for (std::size_t i = 0; i < robots.size(); ++i) {
    p.teammates.push_back({static_cast<int>(i) + 1, Pose2{robots[i], 0.0}});
  }
  return p;
}

Case CaseWith(const std::vector<Vec2>& robots, const Vec2& ball) {
  Case c;
  c.p_F_ball = ball;
  for (std::size_t i = 0; i < robots.size(); ++i) {
    c.teammates.push_back({static_cast<int>(i) + 1, robots[i], {}});
  }
  return c;
}

TEST(CorrespondenceTest, AdaptedPositionsMoveWithTheBall) {
  // Fig. 5: the case's robots keep their offsets from the ball.
  const Case c = CaseWith({{-0.2, 0.0}, {0.8, 0.6}}, {0.0, 0.0});
  const Problem p = ProblemWith({{0.9, 1.4}, {0.4, 0.3}}, {0.5, 0.5});
  const Correspondence k = FindCorrespondence(p, c, CostFunction::kSum, 1.5);
  ASSERT_TRUE(k.feasible);
  EXPECT_TRUE(k.adapted_F[0].isApprox(Vec2(0.3, 0.5)));
  EXPECT_TRUE(k.adapted_F[1].isApprox(Vec2(1.3, 1.1)));
  // Robot 2 (index 1) is next to case teammate 1's spot, robot 1 next to teammate 2's.
  EXPECT_EQ(k.problem_index[0], 1);
  EXPECT_EQ(k.problem_index[1], 0);
  EXPECT_NEAR(k.sum_m,
              (Vec2(0.4, 0.3) - Vec2(0.3, 0.5)).norm() + (Vec2(0.9, 1.4) - Vec2(1.3, 1.1)).norm(),
              1e-12);
}

// Fig. 6: robots 1, 2 and spots A, B on a trapezoid (1A parallel to 2B) whose long side
// b = |1A| = 2 is longer than both diagonals |1B| = |2A| = sqrt(2.5) ~ 1.58. Sum matches along
// the sides c = 1A and d = 2B (2 + 1 = 3 < 3.16); max matches along the diagonals (1.58 < 2),
// and those paths cross at (1, 1/3).
TEST(CorrespondenceTest, Figure6TrapezoidSumAndMaxDisagreeAndMaxPathsCross) {
  const Vec2 r1(0.0, 0.0), r2(0.5, 0.5), a(2.0, 0.0), b(1.5, 0.5);
  ASSERT_LT((b - r1).norm(), (a - r1).norm());
  ASSERT_LT((a - r2).norm(), (a - r1).norm());
  const Problem p = ProblemWith({r1, r2}, {0.0, 0.0});
  const Case c = CaseWith({a, b}, {0.0, 0.0});
  const Correspondence sum = FindCorrespondence(p, c, CostFunction::kSum, 3.0);
  const Correspondence max = FindCorrespondence(p, c, CostFunction::kMax, 3.0);
  const Correspondence max_sum = FindCorrespondence(p, c, CostFunction::kMaxThenSum, 3.0);
  EXPECT_EQ(sum.problem_index[0], 0);  // A <- 1
  EXPECT_EQ(sum.problem_index[1], 1);  // B <- 2
  EXPECT_NEAR(sum.cost.primary, 3.0, 1e-12);
  EXPECT_EQ(max.problem_index[0], 1);  // A <- 2
  EXPECT_EQ(max.problem_index[1], 0);  // B <- 1
  EXPECT_NEAR(max.cost.primary, std::sqrt(2.5), 1e-12);
  EXPECT_EQ(max_sum.problem_index[0], 1);
  // The max paths 1 -> B and 2 -> A cross: the endpoints of each lie on both sides of the other.
  const auto side = [](const Vec2& o, const Vec2& e, const Vec2& q) {
    const Vec2 u = e - o, v = q - o;
    return u.x() * v.y() - u.y() * v.x();
  };
  EXPECT_LT(side(r1, b, r2) * side(r1, b, a), 0.0);
  EXPECT_LT(side(r2, a, r1) * side(r2, a, b), 0.0);
  // The sum paths do not.
  EXPECT_GT(side(r1, a, r2) * side(r1, a, b), 0.0);
}

TEST(CorrespondenceTest, TooFarNamesTheRobotAndTheDistance) {
  // Case teammate 2's spot is 2 m from every robot; the best matching still needs 2 m.
  const Case c = CaseWith({{0.0, 0.0}, {3.0, 0.0}}, {0.0, 0.0});
  const Problem p = ProblemWith({{0.0, 0.1}, {1.0, 0.0}, {0.0, -0.5}}, {0.0, 0.0});
  const Correspondence k = FindCorrespondence(p, c, CostFunction::kSum, 1.5);
  EXPECT_FALSE(k.feasible);
  EXPECT_EQ(k.far_case_index, 1);
  EXPECT_EQ(k.far_problem_index, 1);
  EXPECT_NEAR(k.far_distance_m, 2.0, 1e-12);
  // The threshold applies to each robot: sum picks the best matching among the feasible ones.
  const Case near = CaseWith({{0.0, 0.0}, {2.4, 0.0}}, {0.0, 0.0});
  const Correspondence f = FindCorrespondence(p, near, CostFunction::kSum, 1.5);
  EXPECT_TRUE(f.feasible);
  EXPECT_EQ(f.problem_index[1], 1);
  EXPECT_LE(f.max_m, 1.5);
}

// Brute force over all permutations of the problem's robots (the first m of each assign).
// With `fixed`, only the permutations that give case teammate fixed.case_index that problem
// teammate.
CostKey BruteForce(const Problem& p, const Case& c, CostFunction cost, double thr, bool* feasible,
                   double* minmax, FixedPair fixed = {}) {
  std::vector<int> perm(p.teammates.size());
  std::iota(perm.begin(), perm.end(), 0);
  CostKey best{std::numeric_limits<double>::infinity(), 0.0};
  *feasible = false;
  *minmax = std::numeric_limits<double>::infinity();
  do {
    if (fixed.case_index >= 0 &&
        perm[static_cast<std::size_t>(fixed.case_index)] != fixed.problem_index) {
      continue;
    }
    double sum = 0.0, max = 0.0;
    for (std::size_t i = 0; i < c.teammates.size(); ++i) {
      const double d = (p.teammates[static_cast<std::size_t>(perm[i])].pose.p_F -
                        (c.teammates[i].p_F - c.p_F_ball + p.p_F_ball))
                           .norm();
      sum += d;
      max = std::max(max, d);
    }
    *minmax = std::min(*minmax, max);
    if (max <= thr) {
      const CostKey key = MakeCostKey(cost, sum, max);
      if (!*feasible || key < best) best = key;
      *feasible = true;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

TEST(CorrespondenceTest, AgreesWithBruteForceOnRandomTeams) {
  RandomStream rng(StreamKey(13, 0));
  const auto point = [&] {
    const double x = -2.7 + 5.4 * rng.NextUniform();  // x, then y: one draw per statement
    return Vec2(x, -1.8 + 3.6 * rng.NextUniform());
  };
  int feasible_count = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = 1 + static_cast<int>(rng.NextBits() % 4);
    const int m = 1 + static_cast<int>(rng.NextBits() % static_cast<std::uint64_t>(n));
    std::vector<Vec2> robots, spots;
    for (int i = 0; i < n; ++i) robots.push_back(point());
    for (int i = 0; i < m; ++i) spots.push_back(point());
    const Problem p = ProblemWith(robots, point());
    const Case c = CaseWith(spots, point());
    const double thr = 1.0 + 3.0 * rng.NextUniform();
    for (CostFunction cost : {CostFunction::kSum, CostFunction::kMax, CostFunction::kMaxThenSum}) {
      bool feasible = false;
      double minmax = 0.0;
      const CostKey best = BruteForce(p, c, cost, thr, &feasible, &minmax);
      const Correspondence k = FindCorrespondence(p, c, cost, thr);
      ASSERT_EQ(k.feasible, feasible) << "trial " << trial;
      if (feasible) {
        ++feasible_count;
        EXPECT_NEAR(k.cost.primary, best.primary, 1e-9) << "trial " << trial;
        EXPECT_NEAR(k.cost.secondary, best.secondary, 1e-9) << "trial " << trial;
        // The matching is injective and its distances add up to the reported cost.
        std::array<bool, kMaxTeammates> used{};
        double sum = 0.0;
        for (int i = 0; i < m; ++i) {
          EXPECT_FALSE(used[static_cast<std::size_t>(k.problem_index[i])]);
          used[static_cast<std::size_t>(k.problem_index[i])] = true;
          sum += k.distance_m[i];
          EXPECT_LE(k.distance_m[i], thr);
        }
        EXPECT_NEAR(sum, k.sum_m, 1e-12);
      } else {
        EXPECT_NEAR(k.far_distance_m, minmax, 1e-12) << "trial " << trial;
        EXPECT_GT(k.far_distance_m, thr);
      }
    }
  }
  EXPECT_GT(feasible_count, 1000);  // both branches are exercised
}

TEST(CorrespondenceTest, AFixedRobotAgreesWithBruteForce) {
  RandomStream rng(StreamKey(17, 0));
  const auto point = [&] {
    const double x = -2.7 + 5.4 * rng.NextUniform();  // x, then y: one draw per statement
    return Vec2(x, -1.8 + 3.6 * rng.NextUniform());
  };
  int feasible_count = 0, moved = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = 2 + static_cast<int>(rng.NextBits() % 3);
    const int m = 1 + static_cast<int>(rng.NextBits() % static_cast<std::uint64_t>(n));
    std::vector<Vec2> robots, spots;
    for (int i = 0; i < n; ++i) robots.push_back(point());
    for (int i = 0; i < m; ++i) spots.push_back(point());
    const Problem p = ProblemWith(robots, point());
    const Case c = CaseWith(spots, point());
    const FixedPair fixed{static_cast<int>(rng.NextBits() % static_cast<std::uint64_t>(m)),
                          static_cast<int>(rng.NextBits() % static_cast<std::uint64_t>(n))};
    const double thr = 1.0 + 3.0 * rng.NextUniform();
    bool feasible = false;
    double minmax = 0.0;
    const CostKey best = BruteForce(p, c, CostFunction::kSum, thr, &feasible, &minmax, fixed);
    const Correspondence k = FindCorrespondence(p, c, CostFunction::kSum, thr, fixed);
    ASSERT_EQ(k.feasible, feasible) << "trial " << trial;
    if (!feasible) continue;
    ++feasible_count;
    EXPECT_EQ(k.problem_index[static_cast<std::size_t>(fixed.case_index)], fixed.problem_index);
    EXPECT_NEAR(k.cost.primary, best.primary, 1e-9) << "trial " << trial;
    const Correspondence free = FindCorrespondence(p, c, CostFunction::kSum, thr);
    EXPECT_LE(free.cost.primary, k.cost.primary + 1e-12);  // fixing a robot never helps
    moved += free.problem_index[static_cast<std::size_t>(fixed.case_index)] != fixed.problem_index;
  }
  EXPECT_GT(feasible_count, 500);
  EXPECT_GT(moved, 100);  // the constraint changed the matching in many trials
}

}  // namespace
}  // namespace foresight
