// The seam between the match simulator (match/) and the teams that play in it (Ros et al. 2009,
// sec. 4.1: robots perceive the world, act and send each other messages). A TeamPolicy decides,
// once per control step and robot, what that robot does, from what that robot perceived and was
// told: never from the true state. The simulator plays two policies without knowing how they
// decide; the reactive team, the opponents and the CBR team implement it.
//
// The commands are the actions of the paper's robots (sec. 2.2, 5.1.2): walk and turn (one
// command: a velocity in the robot frame and a turning rate), get the ball (walk to it and grab
// it; a grab can fail), dribble (walk while holding the ball: the same walk command, which the
// simulator executes slower), kick with a kick of the kick model (by index into the match's
// KickModel; the robot stands still while it kicks), release (let a held ball go where it lies,
// in front of the robot, without kicking it), block (a goalie's block: the robot goes
// down across its heading for the robot's block time and gets up again, unable to move) and send
// a message to the teammates (delivered after a latency, possibly lost).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/geometry.h"
#include "models/kick_model.h"

namespace foresight {

// A message between teammates. `kind` and the payload mean what the sending team says they
// mean; the simulator only carries them (and stamps sender and time).
struct TeamMessage {
  int sender = 0;          // robot index within the team
  double sent_time_s = 0;  // stamped by the simulator
  int kind = 0;
  Vec2 p_F{0.0, 0.0};
  double value = 0.0;
  std::array<std::int32_t, 4> words{};  // integers the team defines (a cycle, a case, a mapping)
};

// What one robot knows at one control step. Its own pose and what it is doing are exact; the
// ball and the other robots are as perceived (with the simulator's optional noise).
struct Perception {
  double time_s = 0.0;
  int self = 0;  // index of this robot within its team
  Pose2 pose;    // own pose in F
  bool holding_ball = false;
  bool busy = false;             // grabbing or kicking: the command is ignored until it is done
  Vec2 p_F_ball{0.0, 0.0};       // perceived
  std::vector<Pose2> teammates;  // the whole team by index; entry `self` is the own pose
  std::vector<Pose2> opponents;  // perceived
  double attack_sign = 1.0;      // +1: the team attacks the goal at +x; -1: the one at -x
  std::span<const TeamMessage> inbox;  // messages delivered at this step
};

enum class CommandKind : std::uint8_t { kStand, kWalk, kGetBall, kKick, kBlock, kRelease };
std::string_view CommandKindName(CommandKind kind);

struct RobotCommand {
  CommandKind kind = CommandKind::kStand;
  Vec2 v_R_mps{0.0, 0.0};    // kWalk: velocity in the robot frame (clamped to the robot's speed)
  double turn_radps = 0.0;   // kWalk: turning rate (clamped); counter-clockwise positive
  int kick_index = kNoKick;  // kKick: the kick of the match's kick model
  std::optional<TeamMessage> message;  // sent to every teammate
  // The robot reports that it is moving away from the ball to leave it to a teammate (the
  // reactive team's "backing up", Table 2); the simulator counts how often this begins.
  bool backing_up = false;
};

class TeamPolicy {
 public:
  virtual ~TeamPolicy() = default;
  // One robot's command for this step. A policy object serves one team in one trial; it may
  // keep state per robot (indexed by perception.self) but must not pass anything between its
  // robots except through messages.
  virtual RobotCommand Decide(const Perception& perception) = 0;
  // What the team counted about itself during the trial (e.g. the CBR team's cases retrieved
  // and aborts), read once the trial has ended; the simulator stores them with the trial's
  // result without knowing what they mean. Names are snake_case and stable.
  struct Counter {
    std::string name;
    double value = 0.0;
  };
  virtual std::vector<Counter> Counters() const { return {}; }
  // How the event log names a message of this team (default: its kind as a number).
  virtual std::string MessageName(const TeamMessage& message) const {
    return std::to_string(message.kind);
  }
};

}  // namespace foresight
