// The opponents of the passing experiment (Ros et al. 2009, sec. 5.1.2): "Each robot has a home
// region and he cannot go beyond that region. If the ball is within his home region, then the
// robot moves towards the ball and clears it. Otherwise, the robot remains in the boundary of
// his home region, facing the ball."
//
// Here: with the perceived ball inside its region, or so near it that the robot can grab it
// from inside (within body radius + ball radius + grab reach of the boundary), the robot walks to
// the point in front of the ball where it can grab it (clamped to its region), grabs it and kicks
// it with the configuration's clear kick from the heading it came with (the paper does not say
// where a clearance goes; ours goes away from the robot's side of the ball), first turning with the
// ball, away from the nearest body, while a robot stands in the kick's way (within
// clear_free_distance_m and clear_free_cone of its line), until the ball-holding rule
// (SimulationParams::ball_holding_limit_s, minus the kick's kick_launch_s) makes it kick. Otherwise
// it walks to the point of its region nearest to the ball (on the boundary) and turns to face the
// ball. Every walking target lies in the region and walking never overshoots its target
// (match/robot_motion.h), so the robot's centre never leaves the region (a box, convex).
#pragma once

#include <vector>

#include "match/match_config.h"
#include "models/team_policy.h"

namespace foresight {

class OpponentTeam final : public TeamPolicy {
 public:
  // `config` gives the regions (already mirrored when the attackers attack -x); the clear kick
  // is looked up by name in `kicks` (InputError naming the config file when it is not there).
  OpponentTeam(const MatchConfig& config, const KickModel& kicks, const RobotParams& robot,
               double ball_radius_m, const SimulationParams& sim);
  RobotCommand Decide(const Perception& perception) override;

 private:
  struct Memory {
    bool was_holding = false;
    double holding_since_s = 0.0;
  };
  RobotCommand Clear(Memory& m, const Perception& p) const;

  const MatchConfig* config_;
  int clear_kick_;
  double contact_m_;
  double grab_reach_m_;
  double grab_cone_rad_;
  double dt_s_;
  double release_after_s_;  // kick when the ball has been held this long
  std::vector<Memory> memory_;
};

// The index of the kick `name` in `kicks`, or an InputError "FILE: FIELD: unknown kick ..."
int RequireKick(const KickModel& kicks, const std::string& name, const std::string& file,
                const std::string& field);

}  // namespace foresight
