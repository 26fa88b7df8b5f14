#include "match/trial_result.h"

#include "common/enum_names.h"

namespace foresight {

namespace {

inline constexpr EnumNames<TrialOutcome, kTrialOutcomeCount> kOutcomeNames{{{
    {TrialOutcome::kGoal, "goal"},
    {TrialOutcome::kClose, "close"},
    {TrialOutcome::kBlock, "block"},
    {TrialOutcome::kOut, "out"},
    {TrialOutcome::kPenaltyArea, "penalty_area"},
    {TrialOutcome::kTimeout, "timeout"},
}}};

inline constexpr EnumNames<EventKind, 13> kEventNames{{{
    {EventKind::kGrab, "grab"},
    {EventKind::kGrabFailed, "grab_failed"},
    {EventKind::kSteal, "steal"},
    {EventKind::kKick, "kick"},
    {EventKind::kTouch, "touch"},
    {EventKind::kMessage, "message"},
    {EventKind::kMessageLost, "message_lost"},
    {EventKind::kBackUp, "back_up"},
    {EventKind::kEnd, "end"},
    {EventKind::kKickEnd, "kick_end"},
    {EventKind::kRelease, "release"},
    {EventKind::kBallMoved, "ball_moved"},
    {EventKind::kPenalized, "penalized"},
}}};

inline constexpr EnumNames<Side, 2> kSideNames{
    {{{Side::kAttackers, "attackers"}, {Side::kOpponents, "opponents"}}}};

}  // namespace

std::string_view TrialOutcomeName(TrialOutcome outcome) {
  return kOutcomeNames.Name(outcome);
}

bool IsToGoal(TrialOutcome outcome) {
  return outcome == TrialOutcome::kGoal || outcome == TrialOutcome::kClose ||
         outcome == TrialOutcome::kPenaltyArea;
}

std::string_view EventKindName(EventKind kind) {
  return kEventNames.Name(kind);
}
std::string_view SideName(Side side) {
  return kSideNames.Name(side);
}

}  // namespace foresight
