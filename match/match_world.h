// The state of one trial of the match simulator (match/match.h): the robots (attackers first,
// then opponents), what each is doing, the ball and the messages on their way.
#pragma once

#include <optional>
#include <vector>

#include "match/ball_motion.h"
#include "planner/coarse_world.h"
#include "match/trial_result.h"
#include "models/team_policy.h"

namespace foresight {

enum class Activity : std::uint8_t { kFree, kGrabbing, kKicking, kBlocking };

struct RobotState {
  Side side = Side::kAttackers;
  int index = 0;  // within its team
  Pose2 pose;
  Activity activity = Activity::kFree;
  double busy_until_s = 0.0;
  double launch_at_s = 0.0;  // kicking: when the ball leaves
  Vec2 seen_ball{0.0, 0.0};  // where it perceived the ball this step (get-the-ball walks there)
  int kick_index = kNoKick;
  // Blocking (a goalie): when the block began; its body is a capsule across its heading while
  // the block is down (match/match.h).
  double block_since_s = 0.0;
  // 0: a disc; else how far either side of its centre the body stops a ball's centre (the
  // capsule's half length plus body and ball radius).
  double block_half_span_m = 0.0;
  bool touching = false;
  bool backing_up = false;
  // Penalised by the referee (local game stuck) until then: it stands at the touchline and its
  // team's policy does not decide for it.
  double penalized_until_s = -1.0;
  std::vector<TeamMessage> inbox;
};

struct MatchBall {
  Vec2 p_F{0.0, 0.0};
  std::optional<BallRoll> roll;
  int holder = -1;          // robot holding it, or -1
  int leaving_kicker = -1;  // the kicker, until the ball is clear of its body
};

struct MessageInFlight {
  double deliver_at_s = 0.0;
  Side side = Side::kAttackers;
  TeamMessage message;
};

struct MatchWorld {
  double time_s = 0.0;
  std::vector<RobotState> robots;
  MatchBall ball;
  std::vector<MessageInFlight> messages;
  int kicks_made = 0;  // numbers the kicks' random streams
};

// What the ball's step needs besides the world.
struct BallStepParams {
  double contact_m = 0.0;  // robot centre to ball centre when they touch
  double dt_s = 0.0;
  double touch_tolerance_m = 0.0;
  // The ball-robot restitution (models/physics/<field>.json, materials.restitution.ball_robot:
  // the number physics and the coarse rebounds read).
  double robot_restitution = 0.0;
  // The field's posts and nets (no robots): a rebounding ball rolls on through it.
  const CoarseWorld* field = nullptr;
};

// The ball's step (match/match.h, step 4): held, it sits at the holder's front; rolling, it
// advances, and a body it meets sends it back (ReboundOffBody, match/ball_motion.h) to roll on
// for the rest of the step through the field's posts and nets; after kMaxBodyContactsPerStep
// contacts in one step (a ball jammed between two bodies) it stops where it is. A body that
// overlaps a resting ball pushes it out to the body's edge and stops it. The kicker is ignored
// until the ball is clear of it by touch_tolerance_m or has met another body. Returns the robots
// the ball met this step.
inline constexpr int kMaxBodyContactsPerStep = 8;
std::vector<int> StepBall(MatchWorld& world, const BallStepParams& params);

// A robot as the ball meets it (contact_m: robot centre to ball centre when they touch).
BallBody BodyOf(const RobotState& robot, double contact_m);

}  // namespace foresight
