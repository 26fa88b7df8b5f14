#include "match/reactive_team.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "common/checks.h"
#include "common/error.h"
#include "match/opponent_team.h"
#include "match/robot_motion.h"
#include "models/walk_command.h"
#include "models/model_paths.h"
#include "planner/ball_roll.h"

namespace foresight {

namespace {
// Message kinds of this team.
constexpr int kSupporting = 0;
constexpr int kChasing = 1;
constexpr int kHolding = 2;
// Two field y within this are level: a side chosen by y must not follow the rounding that
// separates a game from its mirror image (sin(pi) is 1.2e-16, not 0).
constexpr double kLevelM = 1e-9;
}  // namespace

void ReactiveParams::Validate() const {
  RequireInRange("dodge_radius_m", dodge_radius_m, 0.0, 5.0);
  RequireInRange("dodge_angle_deg", dodge_angle_rad * kRadToDeg, 0.0, 90.0);
  RequireInRange("aim_tolerance_deg", aim_tolerance_rad * kRadToDeg, 0.1, 180.0);
  RequireInRange("back_off_distance_m", back_off_distance_m, 0.0, 5.0);
  RequireInRange("back_off_release_m", back_off_release_m, 0.0, 5.0);
  RequireInRange("support_behind_m", support_behind_m, -5.0, 5.0);
  RequireInRange("support_side_m", support_side_m, 0.0, 5.0);
  if (role_regions.size() < 2) {
    throw InputError("role_regions: must give one region per attacker (2), got " +
                     std::to_string(role_regions.size()));
  }
  RequireInRange("message_period_s", message_period_s, 0.01, 60.0);
  RequireInRange("report_stale_s", report_stale_s, 0.01, 60.0);
}

ReactiveParams LoadReactiveParams(const std::string& reference,
                                  const std::filesystem::path& models_dir) {
  ReactiveParams p;
  p.file = ResolveModelFile(reference, DataFolder::kMatch, ".", models_dir);
  const JsonDocument doc = JsonDocument::Load(p.file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"name", "sources", "dodge_radius_m", "dodge_angle_deg", "shoot_kick",
                          "aim_tolerance_deg", "back_off_distance_m", "back_off_release_m",
                          "support_behind_m", "support_side_m", "role_regions",
                          "message_period_s", "report_stale_s"});
  RequireSources(root,
                 {"dodge_radius_m", "dodge_angle_deg", "shoot_kick", "aim_tolerance_deg",
                  "back_off_distance_m", "back_off_release_m", "support_behind_m", "support_side_m",
                  "role_regions", "message_period_s", "report_stale_s"});
  p.dodge_radius_m = root.Number("dodge_radius_m");
  p.dodge_angle_rad = root.Number("dodge_angle_deg") * kDegToRad;
  p.shoot_kick = root.String("shoot_kick");
  p.aim_tolerance_rad = root.Number("aim_tolerance_deg") * kDegToRad;
  p.back_off_distance_m = root.Number("back_off_distance_m");
  p.back_off_release_m = root.Number("back_off_release_m");
  p.support_behind_m = root.Number("support_behind_m");
  p.support_side_m = root.Number("support_side_m");
  for (const JsonObject& o : root.ObjectArray("role_regions")) {
    p.role_regions.push_back(ReadFieldBox(o));
  }
  p.message_period_s = root.Number("message_period_s");
  p.report_stale_s = root.Number("report_stale_s");
  WithFile(p.file.string(), [&] { p.Validate(); });
  return p;
}

ReactiveTeam::ReactiveTeam(const ReactiveParams& params, const FieldSpec& field,
                           const KickModel& kicks, const RobotParams& robot,
                           const SimulationParams& sim, int robots)
    : params_(params),
      field_(&field),
      shoot_kick_(RequireKick(kicks, params.shoot_kick, params.file.string(), "shoot_kick")),
      release_after_s_(sim.ball_holding_limit_s - robot.kick_launch_s),
      dribble_speed_mps_(robot.dribble_speed_mps),
      dt_s_(sim.control_step_s),
      memory_(static_cast<std::size_t>(robots)) {
  assert(static_cast<std::size_t>(robots) <= params.role_regions.size());
  const KickSpec& shoot = kicks.kicks[static_cast<std::size_t>(shoot_kick_)];
  shoot_range_m_ = StopDistance(shoot.speed_mps, kicks.rolling_deceleration_mps2);
}

bool ReactiveTeam::ChooseChasing(Memory& m, const Perception& p) const {
  for (const TeamMessage& msg : p.inbox) {
    m.heard = true;
    m.mate_kind = msg.kind;
    m.mate_time_s = msg.sent_time_s;
  }
  if (p.holding_ball) return true;
  // Everyone goes after the ball unless a teammate says it owns it.
  const bool fresh = m.heard && p.time_s - m.mate_time_s <= params_.report_stale_s;
  return !(fresh && m.mate_kind == kHolding);
}

RobotCommand ReactiveTeam::Decide(const Perception& p) {
  Memory& m = memory_[static_cast<std::size_t>(p.self)];
  const double distance_m = (p.p_F_ball - p.pose.p_F).norm();
  const bool chasing = ChooseChasing(m, p);
  if (chasing || p.holding_ball) m.backing_up = false;
  if (p.holding_ball && !m.was_holding) m.holding_since_s = p.time_s;
  m.was_holding = p.holding_ball;
  RobotCommand command;
  if (!p.busy) {
    if (p.holding_ball) {
      command = Hold(m, p);
    } else if (chasing) {
      command.kind = CommandKind::kGetBall;
    } else {
      command = Support(m, p, distance_m);
    }
  }
  const int kind = p.holding_ball ? kHolding : (chasing ? kChasing : kSupporting);
  const bool changed = chasing != m.chasing;
  m.chasing = chasing;
  const bool took_or_released = p.holding_ball != m.was_holding_reported;
  m.was_holding_reported = p.holding_ball;
  if (changed || took_or_released ||
      p.time_s - m.last_report_s >= params_.message_period_s - 1e-9) {
    command.message = TeamMessage{p.self, p.time_s, kind, p.pose.p_F, distance_m};
    m.last_report_s = p.time_s;
  }
  return command;
}

const Pose2* ReactiveTeam::OpponentNearBall(const Perception& p) const {
  for (const Pose2& opponent : p.opponents) {
    if ((opponent.p_F - p.p_F_ball).norm() <= params_.dodge_radius_m) return &opponent;
  }
  return nullptr;
}

RobotCommand ReactiveTeam::Hold(Memory& m, const Perception& p) const {
  const Vec2 goal(p.attack_sign * field_->HalfLength(), 0.0);
  const double goal_heading = HeadingTowards(p.p_F_ball, goal);
  const double aim_error = WrapAngle(goal_heading - p.pose.theta_rad);
  const double to_line_m = field_->HalfLength() - p.attack_sign * p.p_F_ball.x();
  const bool time_up = p.time_s - m.holding_since_s >= release_after_s_;
  const Pose2* opponent = OpponentNearBall(p);  // it blocks the shot: dodge it first
  if ((opponent == nullptr && to_line_m <= shoot_range_m_ &&
       std::abs(aim_error) <= params_.aim_tolerance_rad) ||
      time_up) {
    RobotCommand kick;
    kick.kind = CommandKind::kKick;
    kick.kick_index = shoot_kick_;
    return kick;
  }
  double heading = goal_heading;
  if (opponent != nullptr) {
    // Away from the opponent as seen along the robot's own heading, so that the turn never
    // sweeps the held ball through the opponent standing in the way.
    double side = WrapAngle(HeadingTowards(p.p_F_ball, opponent->p_F) - p.pose.theta_rad);
    // Dead ahead (noiseless scenarios line robots up exactly): dodge towards the middle of the
    // field, where there is room; a rule in field terms, so the mirrored game plays the same.
    // (A ball "on" the middle line is on it within kLevelM: rounding, e.g. sin(pi) in the mirrored
    // game, must not pick the side.)
    if (std::abs(side) < 1e-9) side = (p.p_F_ball.y() >= -kLevelM ? 1.0 : -1.0) * p.attack_sign;
    heading = goal_heading + (side > 0.0 ? -1.0 : 1.0) * params_.dodge_angle_rad;
  }
  RobotCommand walk;
  walk.kind = CommandKind::kWalk;
  const double error = WrapAngle(heading - p.pose.theta_rad);
  walk.turn_radps = error / dt_s_;
  // Walk on only when roughly facing the way to go; turn on the spot with the ball otherwise.
  if (std::abs(error) < 0.25 * kPi) walk.v_R_mps = Vec2(dribble_speed_mps_, 0.0);
  return walk;
}

RobotCommand ReactiveTeam::Support(Memory& m, const Perception& p, double distance_m) const {
  const Vec2& ball = p.p_F_ball;
  const double face = HeadingTowards(p.pose.p_F, ball);
  // Backing up starts nearer than back_off_distance_m and lasts until back_off_release_m
  // further out (hysteresis: one backing-up, not one per step at the edge).
  const double release_m = params_.back_off_distance_m + params_.back_off_release_m;
  m.backing_up = m.backing_up ? distance_m < release_m : distance_m < params_.back_off_distance_m;
  if (m.backing_up) {
    const Vec2 away = distance_m > 1e-6 ? Vec2((p.pose.p_F - ball) / distance_m)
                                        : UnitVector(p.pose.theta_rad + kPi);
    RobotCommand back = WalkTowards(p.pose, ball + release_m * away, face, dt_s_);
    back.backing_up = true;
    return back;
  }
  const double side = p.pose.p_F.y() >= ball.y() - kLevelM ? 1.0 : -1.0;
  Vec2 target(ball.x() - p.attack_sign * params_.support_behind_m,
              ball.y() + side * params_.support_side_m);
  const FieldBox& own = params_.role_regions[static_cast<std::size_t>(p.self)];
  target = (p.attack_sign > 0.0 ? own : own.MirroredX()).Clamp(target);
  const double margin_m = 0.5 * params_.back_off_distance_m;
  target.x() =
      std::clamp(target.x(), -field_->HalfLength() + margin_m, field_->HalfLength() - margin_m);
  target.y() =
      std::clamp(target.y(), -field_->HalfWidth() + margin_m, field_->HalfWidth() - margin_m);
  return WalkTowards(p.pose, target, face, dt_s_);
}

}  // namespace foresight
