// The state of one trial of the match simulator (match/match.h): the robots (attackers first,
// then opponents), what each is doing, the ball and the messages on their way.
#pragma once

#include <optional>
#include <vector>

#include "match/ball_motion.h"
#include "match/trial_result.h"
#include "models/team_policy.h"

namespace foresight {

enum class Activity : std::uint8_t { kFree, kGrabbing, kKicking };

struct RobotState {
  Side side = Side::kAttackers;
  int index = 0;  // within its team
  Pose2 pose;
  Activity activity = Activity::kFree;
  double busy_until_s = 0.0;
  double launch_at_s = 0.0;  // kicking: when the ball leaves
  Vec2 seen_ball{0.0, 0.0};  // where it perceived the ball this step (get-the-ball walks there)
  int kick_index = kNoKick;
  bool touching = false;
  bool backing_up = false;
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

// The ball's step (match/match.h, step 4): held, it sits at the holder's front; rolling, it
// advances and stops dead at the first body it meets (match/ball_motion.h); a body that overlaps
// it pushes it out to the body's edge and stops it. The kicker is ignored until the ball is
// clear of it by touch_tolerance_m.
void StepBall(MatchWorld& world, double contact_m, double dt_s, double touch_tolerance_m);

}  // namespace foresight
