// The outcome vocabulary: every enum value has one name, and statuses are counted.
#include "models/outcome.h"

#include <gtest/gtest.h>

#include <limits>
#include <optional>
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

// The status names files and Python use: each parses back to its status, the codes (files and
// Python store a status by its index) keep their order, and blocked is a status of its own.
TEST(OutcomeTest, StatusNamesRoundTrip) {
  std::vector<std::string> names;
  for (int i = 0; i < kOutcomeStatusCount; ++i) {
    const auto status = static_cast<OutcomeStatus>(i);
    names.emplace_back(OutcomeStatusName(status));
    EXPECT_EQ(ParseOutcomeStatus(names.back()), status) << names.back();
  }
  EXPECT_EQ(names, (std::vector<std::string>{"ok", "missed", "not_settled", "fell", "blocked"}));
  EXPECT_EQ(ParseOutcomeStatus("Blocked"), std::nullopt);
  EXPECT_EQ(ParseOutcomeStatus(""), std::nullopt);
}

// Every field of Outcome takes part in SameBits (and doubles by their bits): changing any one
// of them makes two outcomes differ. A field added to Outcome stops the build in outcome.cc
// until SameBits compares it.
TEST(OutcomeTest, SameBitsComparesEveryFieldBitwise) {
  Outcome a;
  a.p_F_rest = {0.25, -1.5};
  a.time_s = 2.0;
  EXPECT_TRUE(SameBits(a, a));
  std::vector<Outcome> changed(6, a);
  changed[0].p_F_rest.x() = 0.2500000000000001;
  changed[1].p_F_rest.y() = -1.4999999999999998;
  changed[2].category = Category::kOut;
  changed[3].first_contact = Contact::kPost;
  changed[4].time_s = 2.0000000000000004;
  changed[5].status = OutcomeStatus::kBlocked;
  for (std::size_t i = 0; i < changed.size(); ++i) {
    EXPECT_FALSE(SameBits(a, changed[i])) << i;
    EXPECT_FALSE(SameBits(changed[i], a)) << i;
  }
  Outcome zero = a, negative_zero = a;
  zero.time_s = 0.0;
  negative_zero.time_s = -0.0;
  EXPECT_FALSE(SameBits(zero, negative_zero));  // == would call them equal
  Outcome nan = a;
  nan.p_F_rest.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(SameBits(nan, nan));  // == would not
}

TEST(OutcomeTest, CountsEachStatusOnItsOwn) {
  std::vector<Outcome> outcomes(6);
  outcomes[1].status = OutcomeStatus::kMissed;
  outcomes[3].status = OutcomeStatus::kMissed;
  outcomes[4].status = OutcomeStatus::kNotSettled;
  outcomes[5].status = OutcomeStatus::kBlocked;
  StatusCounts counts = CountStatuses(outcomes);
  EXPECT_EQ(counts.missed, 2);
  EXPECT_EQ(counts.not_settled, 1);
  EXPECT_EQ(counts.blocked, 1);  // a blocked stance is not a miss
  counts.Add(CountStatuses({&outcomes[4], 2}));
  EXPECT_EQ(counts.not_settled, 2);
  EXPECT_EQ(counts.blocked, 2);
  EXPECT_EQ(StatusCountsText(counts), "2 missed the ball, 2 did not settle, 0 fell, 2 blocked");
}

}  // namespace
}  // namespace foresight
