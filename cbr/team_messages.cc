#include "cbr/team_messages.h"

namespace foresight {

namespace {
constexpr int kLastKind = static_cast<int>(CbrMessageKind::kAbort);
constexpr int kNoRobot = 0xF;
}  // namespace

std::string_view AbortReasonName(AbortReason reason) {
  switch (reason) {
    case AbortReason::kTimeout:
      return "timeout";
    case AbortReason::kBallMoved:
      return "ball_moved";
    case AbortReason::kPathBlocked:
      return "path_blocked";
    case AbortReason::kBallLost:
      return "ball_lost";
  }
  return "?";
}

std::string_view CbrMessageKindName(CbrMessageKind kind) {
  constexpr std::string_view kNames[] = {"belief", "coordinator", "case", "no_case", "arrived",
                                         "passed", "done",        "end",  "abort"};
  return kNames[static_cast<int>(kind) - kCbrKindBase];
}

bool IsCbrMessage(const TeamMessage& message) {
  return message.kind >= kCbrKindBase && message.kind <= kLastKind;
}

std::optional<CbrMessageKind> CbrKind(const TeamMessage& message) {
  if (!IsCbrMessage(message)) return std::nullopt;
  return static_cast<CbrMessageKind>(message.kind);
}

TeamMessage MakeCbrMessage(CbrMessageKind kind, int cycle, const Vec2& p_F_ball,
                           double ball_distance_m, int word1, int word2) {
  TeamMessage m;
  m.kind = static_cast<int>(kind);
  m.p_F = p_F_ball;
  m.value = ball_distance_m;
  m.words = {cycle, word1, word2, 0};
  return m;
}

std::string CbrMessageName(const TeamMessage& m, std::span<const Case> cases) {
  const auto kind = CbrKind(m);
  if (!kind) return std::to_string(m.kind);
  std::string name = "cbr " + std::string(CbrMessageKindName(*kind)) + " cycle " +
                     std::to_string(m.words[0]);
  const int word = m.words[1];
  switch (*kind) {
    case CbrMessageKind::kCoordinator:
    case CbrMessageKind::kPassed:
      return name + " robot " + std::to_string(word);
    case CbrMessageKind::kCase:
      if (word < 0 || word >= static_cast<int>(cases.size())) return name;
      return name + " " + cases[static_cast<std::size_t>(word)].name;
    case CbrMessageKind::kAbort:
      if (word < 0 || word >= kAbortReasonCount) return name;
      return name + " " + std::string(AbortReasonName(static_cast<AbortReason>(word)));
    default:
      return name;
  }
}

int PackRobots(const CaseRobots& robots) {
  int packed = 0;
  for (int i = kMaxTeammates - 1; i >= 0; --i) {
    const int r = robots[static_cast<std::size_t>(i)];
    packed = (packed << 4) | (r >= 0 && r < kNoRobot ? r : kNoRobot);
  }
  return packed;
}

CaseRobots UnpackRobots(int packed) {
  CaseRobots robots{};
  for (int i = 0; i < kMaxTeammates; ++i) {
    const int r = (packed >> (4 * i)) & 0xF;
    robots[static_cast<std::size_t>(i)] = r == kNoRobot ? -1 : r;
  }
  return robots;
}

}  // namespace foresight
