#include "physics/trial.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "common/error.h"
#include "common/random.h"
#include "physics/ball_placement.h"
#include "physics/bullet_convert.h"
#include "physics/phases.h"

namespace foresight {

namespace {

double ClippedNormal(RandomStream& stream) {
  return std::clamp(stream.NextNormal(), -TrialVariation::kClipSigmas, TrialVariation::kClipSigmas);
}

// A blocked stance plays nothing, so nothing else can have gone wrong; a fall is what went wrong
// first (a fallen robot may also have missed); a missed ball then lies still, so it also settles.
OutcomeStatus StatusOf(bool blocked, bool fell, bool touched, bool settled) {
  if (blocked) return OutcomeStatus::kBlocked;
  if (fell) return OutcomeStatus::kFell;
  if (!touched) return OutcomeStatus::kMissed;
  return settled ? OutcomeStatus::kOk : OutcomeStatus::kNotSettled;
}

Outcome Finish(const BallMonitor& monitor, const PhaseEnd& end, double t_zero_s) {
  Outcome outcome;
  outcome.p_F_rest = end.ball.Planar();
  outcome.category = monitor.category();
  outcome.first_contact = monitor.first_contact();
  outcome.time_s = std::max(0.0, end.t_s - t_zero_s);
  return outcome;
}

}  // namespace

TrialDraw DrawTrial(const TrialVariation& variation, const CarpetParams& carpet,
                    std::uint64_t stream_key, const PlacementClear& clear) {
  RandomStream stream(stream_key);
  TrialDraw draw;
  for (int k = 0;; ++k) {
    // The whole placement is drawn again: x, y and heading are one stance of the robot.
    draw.placement_dx_m = variation.placement_sigma_x_m * ClippedNormal(stream);
    draw.placement_dy_m = variation.placement_sigma_y_m * ClippedNormal(stream);
    draw.placement_dtheta_rad = variation.placement_sigma_theta_rad * ClippedNormal(stream);
    if (!clear || clear(Vec2(draw.placement_dx_m, draw.placement_dy_m))) break;
    if (k + 1 >= kMaxPlacementDraws) {
      throw InputError("trial placement: the ball lay inside the robot in " +
                       std::to_string(kMaxPlacementDraws) +
                       " draws in a row; the motion's ball spot must lie clear of the robot");
    }
    draw.placement_redraws = k + 1;
  }
  draw.speed_factor = 1.0 + variation.motion_speed_sigma_rel * ClippedNormal(stream);
  draw.carpet_factor = 1.0 + carpet.deceleration_sigma_rel * ClippedNormal(stream);
  return draw;
}

KickStart DrawKickStart(const PhysicsScene& scene, const KickRequest& request) {
  const Robot& robot = *scene.robot;
  const KickMotion& motion = robot.motions[request.motion_index];
  const StanceClearance clearance(robot, motion, scene.field->ball.radius_m);
  KickStart start;
  // A ball spot no placement clears is the motion file's fault: the message names it.
  const std::filesystem::path& motion_file =
      robot.spec.kick_motion_files.at(static_cast<std::size_t>(request.motion_index)).second;
  WithFile(motion_file.string(), [&] {
    start.draw = DrawTrial(robot.spec.variation, scene.params.carpet, request.stream,
                           [&](const Vec2& error_m) {
                             return clearance.DepthInsideM(motion.p_R_ball + error_m) <= 0.0;
                           });
  });
  const TrialDraw& d = start.draw;
  // The robot stands so the ball lies at the motion's nominal spot, give or take its placement.
  start.intended_heading_rad = request.state.robot.theta_rad + request.rotation_rad;
  const double heading = start.intended_heading_rad + d.placement_dtheta_rad;
  const Vec2 p_R_ball = motion.p_R_ball + Vec2(d.placement_dx_m, d.placement_dy_m);
  const Vec2 p_F_root = request.state.p_F_ball - Eigen::Rotation2Dd(heading) * p_R_ball;
  start.pose_F_root = PlanarPose(p_F_root.x(), p_F_root.y(), robot.BaseHeightM(motion), heading);
  return start;
}

TrialResult RunKickTrial(const PhysicsScene& scene, const KickRequest& request) {
  const KickMotion& motion = scene.robot->motions[request.motion_index];
  const KickStart start = DrawKickStart(scene, request);
  TrialResult result;
  result.draw = start.draw;
  const TrialDraw& d = result.draw;
  const Carpet carpet(scene.params.carpet, d.carpet_factor);
  const double intended_heading = start.intended_heading_rad;
  const Eigen::Isometry3d& pose_F_root = start.pose_F_root;
  const Vec2 p_F_ball = request.state.p_F_ball;

  const double radius = scene.field->ball.radius_m;
  BallMonitor monitor(scene.lines, p_F_ball, request.record_trace);
  const BallState ball = RollingBall(p_F_ball, radius, 0.0, 0.0);
  const std::optional<SettledStance>& settled = scene.settled_stances[request.motion_index];
  std::optional<SceneRecorder> recorder;
  if (request.scene_rate_hz > 0.0) recorder.emplace(scene, motion, request.scene_rate_hz);
  SceneRecorder* recording = recorder ? &*recorder : nullptr;
  const PhaseEnd kick = RunKickPhase(scene, carpet, motion, pose_F_root, d.speed_factor, ball,
                                     monitor, settled ? &*settled : nullptr, recording);
  result.touched = kick.touched;
  result.launched = kick.launched;
  result.fell = kick.fell;
  result.blocked = kick.blocked;
  result.stance_overlap_m = kick.stance_overlap_m;
  result.max_tilt_rad = kick.max_tilt_rad;
  const double t_zero = kick.touched ? kick.t_first_touch_s : kick.t_s;
  result.t_first_touch_s = t_zero;
  result.t_strike_s = kick.touched ? kick.t_strike_s : kick.t_s;
  if (kick.touched) {
    const Vec2 v = kick.ball.v_F.head<2>();
    result.launch_speed_mps = v.norm();
    result.launch_direction_rad = WrapAngle(std::atan2(v.y(), v.x()) - intended_heading);
    result.p_F_launch = kick.ball.Planar();
    result.t_launch_s = kick.t_s - t_zero;
  }
  const PhaseEnd roll = RunRollPhase(scene, carpet, kick.ball, kick.t_s, monitor, {}, recording);
  result.settled = roll.settled;
  result.outcome = Finish(monitor, roll, t_zero);
  if (recorder) result.scene = recorder->Finish();
  result.outcome.status = StatusOf(result.blocked, result.fell, result.touched, result.settled);
  result.trace = std::move(monitor.trace());
  return result;
}

TrialResult RunRollTrial(const PhysicsScene& scene, const BallState& start, std::uint64_t stream,
                         bool record_trace) {
  TrialResult result;
  result.draw = DrawTrial(TrialVariation{}, scene.params.carpet, stream);
  const Carpet carpet(scene.params.carpet, result.draw.carpet_factor);
  BallMonitor monitor(scene.lines, start.Planar(), record_trace);
  const PhaseEnd roll = RunRollPhase(scene, carpet, start, 0.0, monitor);
  result.touched = result.launched = true;
  result.launch_speed_mps = start.PlanarSpeed();
  result.launch_direction_rad = std::atan2(start.v_F.y(), start.v_F.x());
  result.p_F_launch = start.Planar();
  result.settled = roll.settled;
  result.outcome = Finish(monitor, roll, 0.0);
  result.outcome.status = StatusOf(false, false, true, result.settled);
  result.trace = std::move(monitor.trace());
  return result;
}

}  // namespace foresight
