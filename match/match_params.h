// The figures of the 2-vs-2 match simulator (Ros et al. 2009, sec. 5.2: an extended PuppySim 2),
// read from models/match/*.json. Every figure of those files has an entry in the file's
// "sources" object: where it comes from, or "assumption: why" (RequireSources checks this).
//
// robot (models/match/aibo_ers7.json): an AIBO ERS-7 as the simulator moves it, a disc of
//   body_radius_m that walks in any direction of its frame at up to walk_speed_mps forward,
//   walk_backward_mps backward and walk_sideways_mps sideways (match/robot_motion.h) while
//   turning at up to turn_speed_radps; holding the ball it walks at dribble_speed_mps,
//   dribble_backward_mps and dribble_sideways_mps and turns at dribble_turn_speed_radps. It grabs a ball whose centre lies within grab_reach_m of its
//   front (the body's edge) and within grab_cone_rad of straight ahead; a grab takes
//   grab_time_s and fails with grab_failure_rate; grabbing a ball another robot holds (a steal)
//   then also needs steal_success_rate, and is possible only from within steal_cone_rad of the
//   holder's heading (the held ball lies under its chin, covered by head and forelegs from the
//   sides and behind). A kick takes kick_time_s standing still; the ball leaves kick_launch_s
//   after its start. A block (a goalie's) spreads the body across its heading until it stops a
//   ball whose centre passes within block_half_span_m either side of its centre, over block_down_s, holds for block_hold_s and
//   takes block_recover_s to get up; the robot cannot move meanwhile.
// simulation (models/match/simulation.json): the field, kick model and robot by name; the
//   control step; perception noise (Gaussian sigmas on the perceived ball and other robots,
//   0 = the paper's noiseless simulator); message latency and loss; the referee's "close"
//   margin (sec. 5.1.4); the penalty area (the field file has none); how near a ball must be to
//   a body to count as touching it; the ball-holding rule both teams' policies obey, and the
//   referee's end of a ball fought over by both teams for longer than that rule allows.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

#include "common/json_reader.h"

namespace foresight {

struct RobotParams {
  std::string name;
  double body_radius_m = 0.0;
  double walk_speed_mps = 0.0;
  double turn_speed_radps = 0.0;
  double dribble_speed_mps = 0.0;
  double dribble_turn_speed_radps = 0.0;
  double walk_sideways_mps = 0.0;
  double walk_backward_mps = 0.0;
  double dribble_sideways_mps = 0.0;
  double dribble_backward_mps = 0.0;  // 0: no walking backwards with the ball
  double grab_reach_m = 0.0;
  double grab_cone_rad = 0.0;
  double grab_time_s = 0.0;
  double grab_failure_rate = 0.0;
  double kick_time_s = 0.0;
  double kick_launch_s = 0.0;
  double steal_success_rate = 0.0;
  double steal_cone_rad = 0.0;
  double block_half_span_m = 0.0;
  double block_down_s = 0.0;
  double block_hold_s = 0.0;
  double block_recover_s = 0.0;

  void Validate() const;
};

struct SimulationParams {
  std::filesystem::path file;
  std::string field;  // names in models/fields, models/kicks, models/match
  std::string kicks;
  std::string robot;
  double control_step_s = 0.0;
  double ball_noise_sigma_m = 0.0;
  double robot_noise_sigma_m = 0.0;
  double message_latency_s = 0.0;
  double message_loss_rate = 0.0;
  double close_margin_m = 0.0;
  double penalty_area_depth_m = 0.0;
  double penalty_area_half_width_m = 0.0;
  double touch_tolerance_m = 0.0;
  double ball_holding_limit_s = 0.0;  // a rule both teams obey: release the ball within it
  // The referee's end of a contest (match/match.h): a ball held or fought over within grabbing
  // reach of both teams for longer than ball_holding_limit_s is set down contest_clearance_m
  // clear of every body.
  double contest_clearance_m = 0.0;
  // The league's local game stuck (match/match.h): a ball that stays within stuck_ball_still_m
  // of where it lay for stuck_after_s gets the robot closest to it, if its body's edge is within
  // stuck_proximity_m, penalised for stuck_penalty_s at the touchline.
  double stuck_ball_still_m = 0.0;
  double stuck_after_s = 0.0;
  double stuck_proximity_m = 0.0;
  double stuck_penalty_s = 0.0;

  void Validate() const;
};

// `reference` is a bare name in MODELS/match/ or a path ending in ".json".
RobotParams LoadRobotParams(const std::string& reference, const std::filesystem::path& models_dir);
SimulationParams LoadSimulationParams(const std::string& reference,
                                      const std::filesystem::path& models_dir);

}  // namespace foresight
