// The opponents of the passing experiment (Ros et al. 2009, sec. 5.1.2): "Each robot has a home
// region and he cannot go beyond that region. If the ball is within his home region, then the
// robot moves towards the ball and clears it. Otherwise, the robot remains in the boundary of
// his home region, facing the ball."
//
// A defender: with the perceived ball inside its region, or so near it that the robot can grab
// it from inside (within body radius + ball radius + grab reach of the boundary), it walks to the
// point in front of the ball where it can grab it (clamped to its region) and grabs it.
// Otherwise it walks to the point of its region nearest to the ball and turns to face the ball.
// Every walking target lies in the region and walking never overshoots its target
// (match/robot_motion.h), so the robot's centre never leaves the region (a box, convex).
//
// Its clearance goes away from its own goal, as four-legged defenders cleared: a kick is "safe"
// when its mean direction lies within 90 deg - clear_direction_margin_sd x its direction sd of
// straight upfield (away from the own goal) and no body stands within clear_free_distance_m and
// clear_free_cone_rad of that line. Holding the ball it kicks at once with a safe kick (the clear
// kick first, then the side kicks, towards the nearer side line first: a defender facing its own
// goal kicks sideways); otherwise it
// turns with the ball towards the safe heading of the clear kick nearest its own (ties towards the
// side line the ball is nearer to); when the ball-holding rule makes it kick (held for the limit
// minus kick_launch_s) it kicks the kick whose direction is safest: unblocked first, then the
// most upfield.
//
// The goalie: the paper's (GoalieModel::kRos2009, the default) is one of these robots, its home
// region in the penalty area ("Each robot has a home region ...", the sentence above, says it of
// every opponent); rUNSWift's competition goalie (kRunswift2005) plays match/goalie.h instead.
#pragma once

#include <vector>

#include "match/goalie.h"
#include "match/match_config.h"
#include "models/field_spec.h"
#include "models/team_policy.h"

namespace foresight {

class OpponentTeam final : public TeamPolicy {
 public:
  // `config` gives the regions (already mirrored when the attackers attack -x); the clear kicks
  // are looked up by name in `kicks` (InputError naming the config file when one is not there).
  OpponentTeam(const MatchConfig& config, const FieldSpec& field, const KickModel& kicks,
               const RobotParams& robot, const SimulationParams& sim);
  RobotCommand Decide(const Perception& perception) override;

 private:
  struct Memory {
    bool was_holding = false;
    double holding_since_s = 0.0;
  };
  RobotCommand Defend(const Perception& p) const;
  RobotCommand Clear(Memory& m, const Perception& p) const;
  // How far the kick line from the ball along heading_rad is from a body: the distance of the
  // nearest body within the clearance cone, or +infinity when the line is free.
  double BlockedAt(const Perception& p, double heading_rad) const;
  // Whether a kick's mean direction heading_rad points far enough away from the own goal.
  bool SafeDirection(const Perception& p, double heading_rad, int kick) const;

  const MatchConfig* config_;
  const KickModel* kicks_;
  std::vector<int> clear_kicks_;  // the clear kick first, then the side kicks
  double contact_m_;
  double grab_reach_m_;
  double grab_cone_rad_;
  double dt_s_;
  double release_after_s_;  // kick when the ball has been held this long
  std::vector<Memory> memory_;
  std::vector<Goalie> goalies_;  // one per opponent (used for a kRunswift2005 goalie's index only)
};

// The index of the kick `name` in `kicks`, or an InputError "FILE: FIELD: unknown kick ..."
int RequireKick(const KickModel& kicks, const std::string& name, const std::string& file,
                const std::string& field);

}  // namespace foresight
