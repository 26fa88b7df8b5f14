// The reactive baseline team, after CMDash'06 as Ros et al. 2009 describe it (sec. 5 and 5.3.1):
// "the robot in possession of the ball notifies the rest of the team, and then the other robots
// move towards different directions to avoid collisions"; "the robots always try to go after
// the ball as fast as possible and move alone towards the attacking goal"; the holder dodges an
// opponent within about 0.4 m of the ball by "moving in diagonal (either to the right or to the
// left) while grabbing the ball"; passes happen only by chance.
//
// Each robot, from its own perception and its teammate's messages only:
//  - role: every robot chases the ball (the paper: "the robots always try to go after the ball as
//    fast as possible"; after a kick "both robots will try to get near to the ball", sec. 5.2.1)
//    unless its teammate's last report, at most report_stale_s old, says the teammate holds the
//    ball: the owner has notified the team, and the robot supports. It reports its role (holding,
//    chasing, supporting) when it changes, when it takes or releases the ball, and every
//    message_period_s.
//  - chaser without the ball: get the ball.
//  - holder: turns towards the attacked goal's centre and walks with the ball; with an opponent
//    within dodge_radius_m of the ball it walks dodge_angle_deg off that line, away from the
//    opponent (as seen along its own heading, so it never turns the ball through the opponent).
//    It kicks the shoot kick when the goal line is within the kick's mean roll
//    distance (v^2 / 2a of the kick model), it faces the goal within aim_tolerance_deg and no
//    opponent is within dodge_radius_m of the ball (the paper: such an opponent is "blocking a
//    forward kick", sec. 5.3.1; near the goal the goalie too: "tries to score avoiding the goalie
//    by either turning or dodging side to side"), and the same kick forward when the ball would
//    otherwise leave after the simulation's ball-holding limit (held for the limit minus the
//    kick's kick_launch_s).
//  - supporter (a teammate owns the ball): backs up (walks away from the ball, the "backing up" of
//    Table 2) while it is nearer than back_off_distance_m to the ball, until it is back_off_release_m further; otherwise
//    it walks to the support point support_behind_m behind the ball and support_side_m to its own
//    side, facing the ball, clamped to its role's region (role_regions, one per robot: the roles
//    keep each supporter in its region; the chaser goes wherever the ball is).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "match/match_config.h"
#include "match/match_params.h"
#include "models/field_spec.h"
#include "models/team_policy.h"

namespace foresight {

struct ReactiveParams {
  std::filesystem::path file;
  double dodge_radius_m = 0.0;
  double dodge_angle_rad = 0.0;
  std::string shoot_kick;
  double aim_tolerance_rad = 0.0;
  double back_off_distance_m = 0.0;
  double back_off_release_m = 0.0;
  double support_behind_m = 0.0;
  double support_side_m = 0.0;
  std::vector<FieldBox> role_regions;  // per robot, for attacking +x (x mirrored for -x)
  double message_period_s = 0.0;
  double report_stale_s = 0.0;

  void Validate() const;
};

// `reference`: a bare name in MODELS/match/ ("reactive") or a path ending in ".json".
ReactiveParams LoadReactiveParams(const std::string& reference,
                                  const std::filesystem::path& models_dir);

class ReactiveTeam final : public TeamPolicy {
 public:
  ReactiveTeam(const ReactiveParams& params, const FieldSpec& field, const KickModel& kicks,
               const RobotParams& robot, const SimulationParams& sim, int robots);
  RobotCommand Decide(const Perception& perception) override;

 private:
  struct Memory {
    bool chasing = false;
    bool heard = false;
    int mate_kind = 0;
    double mate_time_s = 0.0;
    double last_report_s = -1e9;
    bool was_holding = false;
    bool was_holding_reported = false;
    bool backing_up = false;
    double holding_since_s = 0.0;
  };
  bool ChooseChasing(Memory& m, const Perception& p) const;
  // The first opponent within dodge_radius_m of the ball, or none.
  const Pose2* OpponentNearBall(const Perception& p) const;
  RobotCommand Hold(Memory& m, const Perception& p) const;
  RobotCommand Support(Memory& m, const Perception& p, double distance_m) const;

  ReactiveParams params_;
  const FieldSpec* field_;
  int shoot_kick_;
  double shoot_range_m_;
  double release_after_s_;  // kick when the ball has been held this long
  double dribble_speed_mps_;
  double dt_s_;
  std::vector<Memory> memory_;
};

}  // namespace foresight
