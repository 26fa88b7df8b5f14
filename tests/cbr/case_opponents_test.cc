// Whether a configuration can field a case's opponents (cbr/case_opponents.h): each opponent in
// a home region of its own, mirrored for a case defending yellow.
#include "cbr/case_opponents.h"

#include <gtest/gtest.h>

#include <vector>

namespace foresight {
namespace {

// The 2D configuration's regions (models/match/2d.json): a midfield defender up to x = 1.3 m
// and a defender from x = 0.6 m, overlapping in between.
const std::vector<FieldBox> kTwoDefenders{{-1.0, 1.3, -1.5, 1.5}, {0.6, 1.9, -1.5, 1.5}};

Case WithOpponents(const std::vector<Vec2>& positions, DefendingGoal goal) {
  Case c;
  c.defending = goal;
  int id = 1;
  for (const Vec2& p : positions) c.opponents.push_back({id++, p, {}});
  return c;
}

TEST(CaseOpponentsTest, TwoOpponentsOnlyOneRegionHoldsAreNotFielded) {
  // Both beyond the midfield defender's region: only the defender can stand there.
  const Case c = WithOpponents({{1.7, 0.3}, {1.9, -0.4}}, DefendingGoal::kCyan);
  EXPECT_FALSE(FieldsCaseOpponents(c, kTwoDefenders));
}

TEST(CaseOpponentsTest, OpponentsInRegionsOfTheirOwnAreFielded) {
  // The first lies in both regions; it must take the midfield defender's for the second to fit.
  const Case c = WithOpponents({{1.0, 0.3}, {1.7, -0.4}}, DefendingGoal::kCyan);
  EXPECT_TRUE(FieldsCaseOpponents(c, kTwoDefenders));
  const Case swapped = WithOpponents({{1.7, -0.4}, {1.0, 0.3}}, DefendingGoal::kCyan);
  EXPECT_TRUE(FieldsCaseOpponents(swapped, kTwoDefenders));
}

TEST(CaseOpponentsTest, ACaseDefendingYellowIsComparedMirrored) {
  const Case c = WithOpponents({{-1.0, 0.3}, {-1.7, -0.4}}, DefendingGoal::kYellow);
  EXPECT_TRUE(FieldsCaseOpponents(c, kTwoDefenders));
  EXPECT_FALSE(FieldsCaseOpponents(WithOpponents({{-1.7, 0.3}, {-1.9, -0.4}},
                                                 DefendingGoal::kYellow),
                                   kTwoDefenders));
}

TEST(CaseOpponentsTest, MoreOpponentsThanRegionsOrNoneAtAll) {
  const std::vector<FieldBox> one{kTwoDefenders[0]};
  EXPECT_FALSE(FieldsCaseOpponents(WithOpponents({{0.0, 0.0}, {0.2, 0.0}}, DefendingGoal::kCyan),
                                   one));
  EXPECT_TRUE(FieldsCaseOpponents(WithOpponents({}, DefendingGoal::kCyan), one));
}

}  // namespace
}  // namespace foresight
