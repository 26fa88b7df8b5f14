// The 2-vs-2 match simulator (Ros et al. 2009, sec. 5.2: an extended PuppySim 2): two attackers
// and the configuration's opponents, each team played by a TeamPolicy (models/team_policy.h),
// from a scenario until the referee ends the trial (match/referee.h).
//
// One control step (SimulationParams::control_step_s), in this order:
//  1. messages whose latency has passed are delivered (each was lost with message_loss_rate);
//  2. every robot perceives (the ball and the other robots with the optional Gaussian noise) and
//     its team's policy decides; a busy robot's command is ignored;
//  3. commands act: walking (slower while holding the ball), getting the ball (walk straight to
//     where the robot sees it, grab it once it truly lies within reach in front: grab_time_s
//     standing, then success with 1 - grab_failure_rate; grabbing a ball another robot holds
//     steals it with steal_success_rate), kicking (a robot that holds the ball stands
//     kick_time_s; kick_launch_s into it the ball leaves through the KickExecutor with a launch
//     drawn from the kick model); moves follow match/robot_collisions.h (bodies never overlap,
//     opponents never leave their regions, nobody leaves the carpet);
//     A held ball can be taken only by a robot within the holder's steal cone (in front of it);
//     releasing leaves a held ball at rest where it lies, in front of the robot; blocking (a
//     goalie) spreads the body across its heading (RobotParams' block figures);
//  4. the ball: held, it sits at the holder's front; rolling, it advances and rebounds off the
//     bodies it meets with the ball-robot restitution (match/match_world.h); resting, a body that
//     walks into it pushes it out to the body's edge;
//  5. touches: a robot touches the ball when the ball meets its body, when its body comes within
//     touch_tolerance_m of it, or when it grabs it; a touch counts when another robot (or nobody
//     since the last kick) touched the ball last; the goalie's touch ends the trial as "block".
//     Each kick's own travel ends in a kick_end event (rest, a body, a grab or the trial's end);
//     the robot that touched the ball last and whether an attacker's kick sent it are recorded;
//  6. contests: a ball held within grabbing reach of the other team begins a contest, which lasts
//     while both teams stay within reach; one that has lasted longer than the ball-holding limit
//     (the league's rule, models/match/simulation.json) with the ball held or at rest is ended:
//     the ball is set down free at the nearest spot on the field contest_clearance_m clear of
//     every body, and counted;
//  7. local game stuck (the league's rule, models/match/simulation.json): a ball that has stayed
//     within stuck_ball_still_m of where it lay for stuck_after_s gets the robot closest to it
//     (within stuck_proximity_m of its body's edge) penalised: it lets go of the ball, stands
//     stuck_penalty_s at the touchline by its own penalty area, and its team does not decide for
//     it meanwhile; counted;
//  8. the referee judges the ball's move; the time limit ends the trial as "timeout".
// Randomness comes from the trial's key only (perception noise, grabs, message loss, kicks), so a
// trial gives the same result on any thread.
#pragma once

#include <cstdint>

#include "match/kick_executor.h"
#include "match/match_config.h"
#include "match/trial_result.h"
#include "models/kick_model.h"
#include "models/team_policy.h"

namespace foresight {

inline constexpr std::uint64_t kMatchKickDomain = 0x6d61746368'6b69ULL;  // "matchki"

// Everything a trial reads; shared by all trials (immutable).
struct MatchSetup {
  const FieldSpec* field = nullptr;
  const KickModel* kicks = nullptr;
  const RobotParams* robot = nullptr;
  const SimulationParams* sim = nullptr;
  const MatchConfig* config = nullptr;  // opponents' roles and the end rules
  const KickExecutor* executor = nullptr;
  double attack_sign = 1.0;     // +1: the attackers attack the goal at +x
  double trace_period_s = 0.0;  // > 0: record a TraceFrame this often
  // The ball-robot restitution (models/physics/<field>.json, materials.restitution.ball_robot).
  double robot_restitution = 0.0;
};

MatchTrialResult RunTrial(const MatchSetup& setup, const Scenario& scenario, TeamPolicy& attackers,
                          TeamPolicy& opponents, std::uint64_t trial_key);

}  // namespace foresight
