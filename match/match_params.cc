#include "match/match_params.h"

#include <string>

#include "common/checks.h"
#include "common/error.h"
#include "common/geometry.h"
#include "models/model_paths.h"

namespace foresight {

void RobotParams::Validate() const {
  RequireInRange("body_radius_m", body_radius_m, 0.01, 1.0);
  RequireInRange("walk_speed_mps", walk_speed_mps, 0.01, 5.0);
  RequireInRange("turn_speed_deg_per_s", turn_speed_radps * kRadToDeg, 1.0, 1000.0);
  RequireInRange("dribble_speed_mps", dribble_speed_mps, 0.01, walk_speed_mps);
  RequireInRange("dribble_turn_speed_deg_per_s", dribble_turn_speed_radps * kRadToDeg, 1.0, 1000.0);
  RequireInRange("walk_sideways_mps", walk_sideways_mps, 0.01, 5.0);
  RequireInRange("walk_backward_mps", walk_backward_mps, 0.0, 5.0);
  RequireInRange("dribble_sideways_mps", dribble_sideways_mps, 0.0, 5.0);
  RequireInRange("dribble_backward_mps", dribble_backward_mps, 0.0, 5.0);
  RequireInRange("grab_reach_m", grab_reach_m, 0.0, 0.5);
  RequireInRange("grab_cone_deg", grab_cone_rad * kRadToDeg, 1.0, 180.0);
  RequireInRange("grab_time_s", grab_time_s, 0.0, 10.0);
  RequireInRange("grab_failure_rate", grab_failure_rate, 0.0, 0.99);
  RequireInRange("kick_time_s", kick_time_s, 0.0, 10.0);
  RequireInRange("kick_launch_s", kick_launch_s, 0.0, kick_time_s);
  RequireInRange("steal_success_rate", steal_success_rate, 0.0, 1.0);
  RequireInRange("steal_cone_deg", steal_cone_rad * kRadToDeg, 0.0, 180.0);
  RequireInRange("block_half_span_m", block_half_span_m, body_radius_m, 1.0);  // >= contact
  RequireInRange("block_down_s", block_down_s, 0.0, 5.0);
  RequireInRange("block_hold_s", block_hold_s, 0.0, 10.0);
  RequireInRange("block_recover_s", block_recover_s, 0.0, 10.0);
}

void SimulationParams::Validate() const {
  RequireInRange("control_step_s", control_step_s, 1e-3, 0.2);
  RequireInRange("ball_noise_sigma_m", ball_noise_sigma_m, 0.0, 1.0);
  RequireInRange("robot_noise_sigma_m", robot_noise_sigma_m, 0.0, 1.0);
  RequireInRange("message_latency_s", message_latency_s, 0.0, 10.0);
  RequireInRange("message_loss_rate", message_loss_rate, 0.0, 1.0);
  RequireInRange("close_margin_m", close_margin_m, 0.0, 2.0);
  RequireInRange("penalty_area_depth_m", penalty_area_depth_m, 0.05, 3.0);
  RequireInRange("penalty_area_half_width_m", penalty_area_half_width_m, 0.05, 3.0);
  RequireInRange("touch_tolerance_m", touch_tolerance_m, 0.0, 0.1);
  RequireInRange("ball_holding_limit_s", ball_holding_limit_s, 0.1, 60.0);
  RequireInRange("contest_clearance_m", contest_clearance_m, 0.0, 1.0);
  RequireInRange("stuck_ball_still_m", stuck_ball_still_m, 0.0, 1.0);
  RequireInRange("stuck_after_s", stuck_after_s, 0.1, 600.0);
  RequireInRange("stuck_proximity_m", stuck_proximity_m, 0.0, 5.0);
  RequireInRange("stuck_penalty_s", stuck_penalty_s, 0.0, 600.0);
}

RobotParams LoadRobotParams(const std::string& reference, const std::filesystem::path& models_dir) {
  const std::filesystem::path file =
      ResolveModelFile(reference, DataFolder::kMatch, ".", models_dir);
  const JsonDocument doc = JsonDocument::Load(file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys(
      {"name", "sources", "body_radius_m", "walk_speed_mps", "turn_speed_deg_per_s",
       "dribble_speed_mps", "dribble_turn_speed_deg_per_s", "walk_sideways_mps",
       "walk_backward_mps", "dribble_sideways_mps", "dribble_backward_mps", "grab_reach_m",
       "grab_cone_deg",
       "grab_time_s", "grab_failure_rate", "kick_time_s", "kick_launch_s", "steal_success_rate",
       "steal_cone_deg", "block_half_span_m", "block_down_s", "block_hold_s", "block_recover_s"});
  RequireSources(root,
                 {"body_radius_m", "walk_speed_mps", "turn_speed_deg_per_s", "dribble_speed_mps",
                  "dribble_turn_speed_deg_per_s", "walk_sideways_mps", "walk_backward_mps",
                  "dribble_sideways_mps", "dribble_backward_mps", "grab_reach_m", "grab_cone_deg",
                  "grab_time_s",
                  "grab_failure_rate", "kick_time_s", "kick_launch_s", "steal_success_rate",
                  "steal_cone_deg", "block_half_span_m", "block_down_s", "block_hold_s",
                  "block_recover_s"});
  RobotParams p;
  p.name = root.String("name");
  p.body_radius_m = root.Number("body_radius_m");
  p.walk_speed_mps = root.Number("walk_speed_mps");
  p.turn_speed_radps = root.Number("turn_speed_deg_per_s") * kDegToRad;
  p.dribble_speed_mps = root.Number("dribble_speed_mps");
  p.dribble_turn_speed_radps = root.Number("dribble_turn_speed_deg_per_s") * kDegToRad;
  p.walk_sideways_mps = root.Number("walk_sideways_mps");
  p.walk_backward_mps = root.Number("walk_backward_mps");
  p.dribble_sideways_mps = root.Number("dribble_sideways_mps");
  p.dribble_backward_mps = root.Number("dribble_backward_mps");
  p.grab_reach_m = root.Number("grab_reach_m");
  p.grab_cone_rad = root.Number("grab_cone_deg") * kDegToRad;
  p.grab_time_s = root.Number("grab_time_s");
  p.grab_failure_rate = root.Number("grab_failure_rate");
  p.kick_time_s = root.Number("kick_time_s");
  p.kick_launch_s = root.Number("kick_launch_s");
  p.steal_success_rate = root.Number("steal_success_rate");
  p.steal_cone_rad = root.Number("steal_cone_deg") * kDegToRad;
  p.block_half_span_m = root.Number("block_half_span_m");
  p.block_down_s = root.Number("block_down_s");
  p.block_hold_s = root.Number("block_hold_s");
  p.block_recover_s = root.Number("block_recover_s");
  WithFile(file.string(), [&] { p.Validate(); });
  return p;
}

SimulationParams LoadSimulationParams(const std::string& reference,
                                      const std::filesystem::path& models_dir) {
  SimulationParams p;
  p.file = ResolveModelFile(reference, DataFolder::kMatch, ".", models_dir);
  const JsonDocument doc = JsonDocument::Load(p.file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"field", "kicks", "robot", "sources", "control_step_s",
                          "ball_noise_sigma_m", "robot_noise_sigma_m", "message_latency_s",
                          "message_loss_rate", "close_margin_m", "penalty_area_depth_m",
                          "penalty_area_half_width_m", "touch_tolerance_m",
                          "ball_holding_limit_s", "contest_clearance_m", "stuck_ball_still_m",
                          "stuck_after_s", "stuck_proximity_m", "stuck_penalty_s"});
  RequireSources(
      root, {"control_step_s", "ball_noise_sigma_m", "robot_noise_sigma_m", "message_latency_s",
             "message_loss_rate", "close_margin_m", "penalty_area_depth_m",
             "penalty_area_half_width_m", "touch_tolerance_m", "ball_holding_limit_s",
             "contest_clearance_m", "stuck_ball_still_m", "stuck_after_s", "stuck_proximity_m",
             "stuck_penalty_s"});
  p.field = root.String("field");
  p.kicks = root.String("kicks");
  p.robot = root.String("robot");
  p.control_step_s = root.Number("control_step_s");
  p.ball_noise_sigma_m = root.Number("ball_noise_sigma_m");
  p.robot_noise_sigma_m = root.Number("robot_noise_sigma_m");
  p.message_latency_s = root.Number("message_latency_s");
  p.message_loss_rate = root.Number("message_loss_rate");
  p.close_margin_m = root.Number("close_margin_m");
  p.penalty_area_depth_m = root.Number("penalty_area_depth_m");
  p.penalty_area_half_width_m = root.Number("penalty_area_half_width_m");
  p.touch_tolerance_m = root.Number("touch_tolerance_m");
  p.ball_holding_limit_s = root.Number("ball_holding_limit_s");
  p.contest_clearance_m = root.Number("contest_clearance_m");
  p.stuck_ball_still_m = root.Number("stuck_ball_still_m");
  p.stuck_after_s = root.Number("stuck_after_s");
  p.stuck_proximity_m = root.Number("stuck_proximity_m");
  p.stuck_penalty_s = root.Number("stuck_penalty_s");
  WithFile(p.file.string(), [&] { p.Validate(); });
  return p;
}

}  // namespace foresight
