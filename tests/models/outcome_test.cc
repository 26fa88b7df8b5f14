// The outcome vocabulary: every enum value has one name, and statuses are counted.
#include "models/outcome.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace foresight {
namespace {

TEST(OutcomeTest, EveryValueHasItsOwnName) {
  std::set<std::string> names;
  for (int i = 0; i < kCategoryCount; ++i)
    names.insert(std::string(CategoryName(static_cast<Category>(i))));
  EXPECT_EQ(names, (std::set<std::string>{"infield", "opp_goal", "own_goal", "out"}));
  names.clear();
  for (int i = 0; i < kContactCount; ++i)
    names.insert(std::string(ContactName(static_cast<Contact>(i))));
  EXPECT_EQ(names.size(), static_cast<std::size_t>(kContactCount));
  EXPECT_EQ(OutcomeStatusName(OutcomeStatus::kNotSettled), "not_settled");
}

TEST(OutcomeTest, CountsMissedAndUnsettledOutcomes) {
  std::vector<Outcome> outcomes(6);
  outcomes[1].status = OutcomeStatus::kMissed;
  outcomes[3].status = OutcomeStatus::kMissed;
  outcomes[4].status = OutcomeStatus::kNotSettled;
  StatusCounts counts = CountStatuses(outcomes);
  EXPECT_EQ(counts.missed, 2);
  EXPECT_EQ(counts.not_settled, 1);
  counts.Add(CountStatuses({&outcomes[4], 1}));
  EXPECT_EQ(counts.not_settled, 2);
  EXPECT_EQ(StatusCountsText(counts), "2 missed the ball, 2 did not settle, 0 fell");
}

}  // namespace
}  // namespace foresight
