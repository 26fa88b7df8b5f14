// One physics trial: a robot kicks the ball (or a ball is set rolling) and the ball comes to rest.
//
// The variation between trials comes only from physical causes, drawn from the trial's own
// stream (docs/ARCHITECTURE.md, "One physics trial": never from the kick model's sigmas): the
// robot's placement relative to the ball (x, y in R, heading), the motion's playback speed, and the
// carpet's deceleration factor. A placement that would put the ball inside the robot is drawn
// again (physics/ball_placement.h says why), and the trial counts the rejected draws.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "models/outcome.h"
#include "models/scene_trace.h"
#include "physics/ball_state.h"
#include "physics/physics_scene.h"

namespace foresight {

struct TrialDraw {
  double placement_dx_m = 0.0;  // ball offset error along R's x
  double placement_dy_m = 0.0;  // ... along R's y
  double placement_dtheta_rad = 0.0;
  double speed_factor = 1.0;   // motion playback speed (1 = as written)
  double carpet_factor = 1.0;  // factor on the carpet's deceleration
  // Placement draws rejected before this one because they put the ball inside the robot.
  int placement_redraws = 0;
};

// Whether a placement error (x, y in R) leaves the ball clear of the robot.
using PlacementClear = std::function<bool(const Vec2& placement_error_m)>;
// A trial that has rejected this many placements in a row stops with an InputError: the
// motion's nominal spot then lies deeper inside the robot than its placement error reaches.
inline constexpr int kMaxPlacementDraws = 1000;

// Draws the placement (x, y, heading; again while `clear` says no), then the playback speed
// and the carpet factor, in that order from the trial's stream. Without `clear` every
// placement is accepted.
TrialDraw DrawTrial(const TrialVariation& variation, const CarpetParams& carpet,
                    std::uint64_t stream, const PlacementClear& clear = {});

struct TrialResult {
  Outcome outcome;
  TrialDraw draw;
  bool touched = false;   // the robot hit the ball
  bool launched = false;  // ... and it left the foot rolling without sliding within the kick phase
  bool settled = false;   // it came to rest within the time limit
  bool fell = false;      // the robot fell during the kick (floating base)
  // The robot could not take its stance: a post, net or obstacle robot stood where it must
  // (floating base). The motion was not played; the ball lies untouched (status blocked).
  bool blocked = false;
  double stance_overlap_m = 0.0;  // how deep the stance reached into them
  double max_tilt_rad = 0.0;      // the robot torso's largest tilt in the kick (floating base)
  // The launch: the ball's speed and direction once it rolls freely after the kick. The
  // direction is in the intended robot frame (the robot's heading after the turn around the
  // ball, before the placement error), so placement errors show up in it as they would on a
  // real robot.
  double launch_speed_mps = 0.0;
  double launch_direction_rad = 0.0;
  Vec2 p_F_launch{0.0, 0.0};
  double t_launch_s = 0.0;       // since the first touch
  double t_first_touch_s = 0.0;  // since the motion's start (the trace's clock)
  // The strike, when the robot's touch gave the ball a launch's speed (an earlier graze that left
  // it nearly at rest is the first touch, not the strike; physics/phases.h), on the same clock.
  double t_strike_s = 0.0;
  std::vector<TracePoint> trace;    // filled on request; times since the motion's start
  std::optional<SceneTrace> scene;  // the whole scene for the viewer, on request
};

struct KickRequest {
  DrawnState state;           // robot pose (heading before the turn) and ball position in F
  int motion_index = 0;       // into scene.robot->motions
  double rotation_rad = 0.0;  // turn around the ball before the kick
  std::uint64_t stream = 0;
  bool record_trace = false;
  double scene_rate_hz = 0.0;  // > 0: record the scene (physics/scene_recorder.h) at this rate
};

// A kick trial's start: its draw and where the robot's root frame stands in F (the ball lies at
// request.state.p_F_ball, at the motion's nominal spot plus the placement error in R).
struct KickStart {
  TrialDraw draw;
  Eigen::Isometry3d pose_F_root = Eigen::Isometry3d::Identity();
  double intended_heading_rad = 0.0;  // the robot's heading after the turn, before the error
};
KickStart DrawKickStart(const PhysicsScene& scene, const KickRequest& request);

TrialResult RunKickTrial(const PhysicsScene& scene, const KickRequest& request);

// A ball set rolling (without a robot) on the scene's carpet: the free-roll checks and bench.
// `stream` draws the carpet factor only.
TrialResult RunRollTrial(const PhysicsScene& scene, const BallState& start, std::uint64_t stream,
                         bool record_trace);

}  // namespace foresight
