// The reactive baseline team, after CMDash'06 as Ros et al. 2009 describe it (sec. 5, 5.2.1 and
// 5.3), with the low-level play of rUNSWift 2005's code release where the paper is silent. Each
// rule with the sentence it comes from; the figures are in models/match/reactive.json.
//
// Each robot, from its own perception and its teammate's messages only:
//  - role: "the robots always try to go after the ball as fast as possible" (sec. 5) and after a
//    kick "both robots will try to get near to the ball" (sec. 5.2.1), unless "the robot in
//    possession of the ball notifies the rest of the team" (sec. 5): a robot whose teammate's
//    last report, at most report_stale_s old, says it holds the ball supports. It reports its
//    role (holding, chasing, supporting) when it changes, when it takes or lets go of the ball,
//    and every message_period_s.
//  - chaser: gets the ball; for regrab_delay_s after its own kick or release it only follows it
//    (rUNSWift: no grab within 60 frames of a grab-kick).
//  - holder, with an opponent within dodge_radius_m of the ball and not behind it: "the only
//    chance for avoiding the opponent is to dodge it, moving in diagonal (either to the right or
//    to the left) while grabbing the ball" (sec. 5.3.1): it walks with the ball dodge_angle_deg
//    off the way to the goal, away from the opponent.
//  - holder, no such opponent, the goal line beyond the shoot kick's mean roll: "robot A first
//    performs a forward kick" (sec. 5.3.1), "getting rid of the defender and kicking the ball
//    forward": it turns with the ball until the shoot kick's mean direction points at the goal
//    centre within aim_tolerance_deg and kicks it (aimed there from the field, the kick's mean
//    roll ends in the field or in the goal: the field is convex).
//  - holder within the shoot kick's mean roll of the goal line: it "tries to score avoiding the
//    goalie by either turning or dodging side to side" (sec. 5.3.1): it turns with the ball to
//    the best gap the bodies in front leave in the goal's mouth (match/goal_gap.h, rUNSWift's
//    best gap) and shoots once it faces inside the gap with gap_padding of its width to spare;
//    with no gap it walks on with the ball towards the goal (and dodges whoever comes near).
//  - holder at the ball-holding limit (held for the limit minus the kick's kick_launch_s): no
//    blind kick; as rUNSWift's grab timeout, it shoots when the gap lies ahead at all and lets
//    the ball go otherwise.
//  - supporter: "the other robots move towards different directions to avoid collisions"
//    (sec. 5): a supporter in the holder's way (rUNSWift's sGetOutOfTheWay: within in_the_way_m
//    of the line from the ball to the goal, between them, within in_the_way_range_m of the ball)
//    steps step_aside_m away from that line, the "backing up" of Table 2, until it is
//    back_off_release_m further out; otherwise "robot B moves towards the attacking goal,
//    avoiding to intercept the ball" (sec. 5.3.2, Fig. 16b): it waits support_ahead_m ahead of
//    the ball along that line and support_side_m to its own side of it, facing the ball, within
//    its role's region (role_regions, one per robot; the chaser goes wherever the ball is).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "match/goal_gap.h"
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
  double gap_padding = 0.0;  // share of the gap's width
  double regrab_delay_s = 0.0;
  double in_the_way_m = 0.0;
  double in_the_way_range_m = 0.0;
  double step_aside_m = 0.0;
  double back_off_release_m = 0.0;
  double support_ahead_m = 0.0;
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
    double let_go_s = -1e9;  // its last kick or release
  };
  bool ChooseChasing(Memory& m, const Perception& p) const;
  // The first opponent within dodge_radius_m of the ball that is not behind it along
  // heading_rad, or none.
  const Pose2* OpponentBlocking(const Perception& p, double heading_rad) const;
  RobotCommand Hold(Memory& m, const Perception& p) const;
  RobotCommand Dodge(const Perception& p, const Pose2& opponent, double goal_heading) const;
  RobotCommand DribbleTowards(const Perception& p, double heading_rad) const;
  std::optional<HeadingInterval> Gap(const Perception& p) const;
  RobotCommand Chase(const Memory& m, const Perception& p) const;
  RobotCommand Support(Memory& m, const Perception& p, double distance_m) const;

  ReactiveParams params_;
  const FieldSpec* field_;
  const KickModel* kicks_;
  int shoot_kick_;
  double shoot_range_m_;
  double release_after_s_;  // let go of the ball when it has been held this long
  double dribble_speed_mps_;
  double body_radius_m_;
  double contact_m_;
  double grab_reach_m_;
  double dt_s_;
  std::vector<Memory> memory_;
};

}  // namespace foresight
