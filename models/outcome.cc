#include "models/outcome.h"

#include "common/enum_names.h"
#include "common/same_bits.h"

namespace foresight {
namespace {

constexpr EnumNames<Category, kCategoryCount> kCategoryNames{{{
    {Category::kInfield, "infield"},
    {Category::kOppGoal, "opp_goal"},
    {Category::kOwnGoal, "own_goal"},
    {Category::kOut, "out"},
}}};

constexpr EnumNames<Contact, kContactCount> kContactNames{{{
    {Contact::kNone, "none"},
    {Contact::kPost, "post"},
    {Contact::kNet, "net"},
    {Contact::kObstacle, "obstacle"},
    {Contact::kRobot, "robot"},
}}};

constexpr EnumNames<OutcomeStatus, kOutcomeStatusCount> kStatusNames{{{
    {OutcomeStatus::kOk, "ok"},
    {OutcomeStatus::kMissed, "missed"},
    {OutcomeStatus::kNotSettled, "not_settled"},
    {OutcomeStatus::kFell, "fell"},
    {OutcomeStatus::kBlocked, "blocked"},
}}};

}  // namespace

std::string_view CategoryName(Category category) {
  return kCategoryNames.Name(category);
}
std::string_view ContactName(Contact contact) {
  return kContactNames.Name(contact);
}
std::string_view OutcomeStatusName(OutcomeStatus status) {
  return kStatusNames.Name(status);
}
std::optional<OutcomeStatus> ParseOutcomeStatus(std::string_view name) {
  return kStatusNames.Parse(name);
}

void StatusCounts::Add(const StatusCounts& other) {
  missed += other.missed;
  not_settled += other.not_settled;
  fell += other.fell;
  blocked += other.blocked;
}

std::string StatusCountsText(const StatusCounts& counts) {
  return std::to_string(counts.missed) + " missed the ball, " + std::to_string(counts.not_settled) +
         " did not settle, " + std::to_string(counts.fell) + " fell, " +
         std::to_string(counts.blocked) + " blocked";
}

// A field added to Outcome must be added to SameBits too; this stops the build until it is.
static_assert(AggregateFieldCount<Outcome>() == 5, "SameBits(Outcome) must compare every field");

bool SameBits(const Outcome& a, const Outcome& b) {
  return SameBits(a.p_F_rest.x(), b.p_F_rest.x()) && SameBits(a.p_F_rest.y(), b.p_F_rest.y()) &&
         a.category == b.category && a.first_contact == b.first_contact &&
         SameBits(a.time_s, b.time_s) && a.status == b.status;
}

StatusCounts CountStatuses(std::span<const Outcome> outcomes) {
  StatusCounts counts;
  for (const Outcome& o : outcomes) {
    counts.missed += o.status == OutcomeStatus::kMissed ? 1 : 0;
    counts.not_settled += o.status == OutcomeStatus::kNotSettled ? 1 : 0;
    counts.fell += o.status == OutcomeStatus::kFell ? 1 : 0;
    counts.blocked += o.status == OutcomeStatus::kBlocked ? 1 : 0;
  }
  return counts;
}

}  // namespace foresight
