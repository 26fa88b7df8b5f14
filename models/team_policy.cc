#include "models/team_policy.h"

#include "common/enum_names.h"

namespace foresight {

namespace {
inline constexpr EnumNames<CommandKind, 6> kCommandKindNames{{{
    {CommandKind::kStand, "stand"},
    {CommandKind::kWalk, "walk"},
    {CommandKind::kGetBall, "get_ball"},
    {CommandKind::kKick, "kick"},
    {CommandKind::kBlock, "block"},
    {CommandKind::kRelease, "release"},
}}};
}  // namespace

std::string_view CommandKindName(CommandKind kind) {
  return kCommandKindNames.Name(kind);
}

}  // namespace foresight
