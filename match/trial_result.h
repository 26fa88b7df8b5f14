// What one trial of the match simulator produced: the referee's outcome class (Ros et al. 2009,
// sec. 5.1.4 and 5.2.2), the per-trial counters the paper's tables report, the event log and,
// on request, the trace of every robot and the ball.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/geometry.h"
#include "models/team_policy.h"

namespace foresight {

// goal: the ball enters the attacked goal. close: it goes out over the attacked goal line
// within the referee's close margin of a post (SimulationParams::close_margin_m). block: the
// goalie touches (stops, grabs or kicks) the ball. out: any other ball out of the field,
// including into the attackers' own goal. penalty_area: (2D only) the ball enters the attacked
// penalty area, which the paper counts as "to goal". timeout: the time limit passed.
enum class TrialOutcome : std::uint8_t { kGoal, kClose, kBlock, kOut, kPenaltyArea, kTimeout };
inline constexpr int kTrialOutcomeCount = 6;
std::string_view TrialOutcomeName(TrialOutcome outcome);
// goal, close and penalty_area: the paper's "to goal" balls.
bool IsToGoal(TrialOutcome outcome);

enum class EventKind : std::uint8_t {
  kGrab,         // a grab succeeded: the robot holds the ball
  kGrabFailed,   // a grab failed
  kSteal,        // a grab took the ball from a robot that held it
  kKick,         // the ball left a kick (detail: the kick's name)
  kTouch,        // a robot's body began touching the ball
  kMessage,      // a message was sent (detail: its kind)
  kMessageLost,  // a message was lost
  kBackUp,       // an attacker began backing up
  kEnd,          // the trial ended (detail: the outcome)
  // A kick's own travel ended (robot: the kicker; detail: "rest", "body" when it met a robot,
  // "grab" when one took it, "end" when the trial ended first). With the kick event before it,
  // it gives how far and which way the kick moved the ball.
  kKickEnd,
  kRelease,    // a holder let the ball go without kicking it
  kBallMoved,  // the referee set down a ball both teams fought over too long (robot 0, unused)
  kPenalized,  // the referee called local game stuck on this robot (detail: "local_game_stuck")
};
std::string_view EventKindName(EventKind kind);

enum class Side : std::uint8_t { kAttackers, kOpponents };
std::string_view SideName(Side side);

struct MatchEvent {
  double time_s = 0.0;
  EventKind kind = EventKind::kTouch;
  Side side = Side::kAttackers;
  int robot = 0;
  Vec2 p_F_ball{0.0, 0.0};
  std::string detail;
};

struct TrialCounters {
  // Per opponent: touches begun (grabs included) while another robot, or nobody since the last
  // kick, had touched the ball last: how often it got at the ball (the paper's possession).
  std::vector<int> opponent_touches;
  std::vector<int> opponent_kicks;    // per opponent
  std::vector<int> attacker_backups;  // per attacker: backing-ups begun
  std::vector<int> attacker_kicks;
  int grabs_failed = 0;
  // Kicks whose executor reported a status other than ok (physics: the foot missed the ball, it
  // had not settled at the time limit, the robot fell, or a post, net or robot stood where it
  // must stand and blocked the kick); they still count as what happened.
  int kicks_missed = 0;
  int kicks_not_settled = 0;
  int kicks_fell = 0;
  int kicks_blocked = 0;
  double time_s = 0.0;
  // Who caused the end: the robot that last touched, grabbed or kicked the ball (side -1: no
  // robot ever did), and whether the last kick was an attacker's with no opponent touching the
  // ball after it ("to goal by the attackers").
  int last_touch_side = -1;
  int last_touch_robot = -1;
  bool attacker_kick_sent = false;
  // Attackers' kicks whose roll, had no robot been in its way, would have entered the attacked
  // goal (the executor's outcome: the coarse roll through posts and nets), and how many of them
  // the goalie touched before their travel ended (saves).
  int shots_on_target = 0;
  int shots_saved = 0;
  // How often the referee set down a ball robots of both teams had fought over for longer than
  // the ball-holding rule allows (match/match.h).
  int contests_resolved = 0;
  // How often the referee called local game stuck and penalised a robot (match/match.h).
  int stuck_penalties = 0;
};

// Every robot and the ball at one time (attackers first, then opponents).
struct TraceFrame {
  double time_s = 0.0;
  Vec2 p_F_ball{0.0, 0.0};
  std::vector<Pose2> robots;
};

struct MatchTrialResult {
  TrialOutcome outcome = TrialOutcome::kTimeout;
  TrialCounters counters;
  std::vector<MatchEvent> events;
  std::vector<TraceFrame> trace;  // empty unless asked for
  std::vector<TeamPolicy::Counter> attacker_counters;  // the attackers' policy's own counters
};

}  // namespace foresight
