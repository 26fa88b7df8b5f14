// The CBR team's messages (Ros et al. 2009, sec. 4.1: robots tell each other the coordinator,
// the retrieved case and its correspondence, their state, the end of a case and aborts) on the
// match's TeamMessage (models/team_policy.h). Every message also carries its sender's beliefs:
// p_F is where it sees the ball and value its distance to it, so the robot that chooses the
// coordinator knows who is closest to the ball without a message of its own for that, and
// words[kKickingWord] is 1 while the sender is in a kick motion, so that no cycle starts for a
// ball that is about to leave.
//
// words[0] is the cycle: a cycle is one retrieval and its reuse. The robot that chooses the
// coordinator numbers it; a robot acts only on messages of its own or a newer cycle, so a late
// or repeated message of an old cycle cannot revive a case.
// Kinds from kCbrKindBase on are the CBR team's; smaller kinds belong to the default behaviour
// (the reactive team, which the CBR team plays when it has no case).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "cbr/case.h"
#include "cbr/correspondence.h"
#include "models/team_policy.h"

namespace foresight {

inline constexpr int kCbrKindBase = 100;
inline constexpr int kKickingWord = 3;  // the sender is in a kick motion (1) or not (0)

enum class CbrMessageKind {
  kBelief = kCbrKindBase,  // beliefs only
  kCoordinator,            // words[1]: the coordinator's robot index
  kCase,                   // words[1]: case index; words[2]: the correspondence (PackRobots)
  kNoCase,                 // the coordinator retrieved nothing
  kArrived,                // the sender is at its adapted position
  kPassed,                 // the sender kicked its pass; words[1]: the receiver's robot index
  kDone,                   // the sender finished its actions
  kEnd,                    // the coordinator heard everyone finish: a new cycle
  kAbort,                  // words[1]: the AbortReason
};

enum class AbortReason { kTimeout, kBallMoved, kPathBlocked, kBallLost };
inline constexpr int kAbortReasonCount = 4;
std::string_view AbortReasonName(AbortReason reason);
std::string_view CbrMessageKindName(CbrMessageKind kind);  // "belief", "coordinator", "case", ...

bool IsCbrMessage(const TeamMessage& message);
std::optional<CbrMessageKind> CbrKind(const TeamMessage& message);

TeamMessage MakeCbrMessage(CbrMessageKind kind, int cycle, const Vec2& p_F_ball,
                           double ball_distance_m, int word1 = 0, int word2 = 0);

// How the event log names a CBR message: "cbr case cycle 3 back_pass/mirror_y", "cbr abort cycle
// 4 ball_lost", "cbr coordinator cycle 2 robot 1", ...; `cases` are the team's (for case names).
std::string CbrMessageName(const TeamMessage& message, std::span<const Case> cases);

// The correspondence as robot indices per case teammate (-1: none), four bits each.
using CaseRobots = std::array<int, kMaxTeammates>;
int PackRobots(const CaseRobots& robots);
CaseRobots UnpackRobots(int packed);

}  // namespace foresight
