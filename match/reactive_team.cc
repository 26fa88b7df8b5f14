#include "match/reactive_team.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "common/checks.h"
#include "common/error.h"
#include "match/opponent_team.h"
#include "models/model_paths.h"
#include "models/walk_command.h"
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

RobotCommand KickCommand(int kick) {
  RobotCommand c;
  c.kind = CommandKind::kKick;
  c.kick_index = kick;
  return c;
}

// The sign of a side chosen by a field coordinate, level counting as +1.
double SideOf(double value) { return value >= -kLevelM ? 1.0 : -1.0; }
}  // namespace

void ReactiveParams::Validate() const {
  RequireInRange("dodge_radius_m", dodge_radius_m, 0.0, 5.0);
  RequireInRange("dodge_angle_deg", dodge_angle_rad * kRadToDeg, 0.0, 90.0);
  RequireInRange("aim_tolerance_deg", aim_tolerance_rad * kRadToDeg, 0.1, 180.0);
  RequireInRange("gap_padding", gap_padding, 0.0, 0.49);
  RequireInRange("regrab_delay_s", regrab_delay_s, 0.0, 60.0);
  RequireInRange("in_the_way_m", in_the_way_m, 0.0, 5.0);
  RequireInRange("in_the_way_range_m", in_the_way_range_m, 0.0, 10.0);
  RequireInRange("step_aside_m", step_aside_m, 0.01, 5.0);
  RequireInRange("back_off_release_m", back_off_release_m, 0.0, 5.0);
  RequireInRange("support_ahead_m", support_ahead_m, -5.0, 5.0);
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
  const std::vector<std::string_view> figures{
      "dodge_radius_m",     "dodge_angle_deg",  "shoot_kick",         "aim_tolerance_deg",
      "gap_padding",        "regrab_delay_s",   "in_the_way_m",       "in_the_way_range_m",
      "step_aside_m",       "back_off_release_m", "support_ahead_m",  "support_side_m",
      "role_regions",       "message_period_s", "report_stale_s"};
  std::vector<std::string_view> keys{"name", "sources"};
  keys.insert(keys.end(), figures.begin(), figures.end());
  root.RejectUnknownKeys(keys);
  RequireSources(root, figures);
  p.dodge_radius_m = root.Number("dodge_radius_m");
  p.dodge_angle_rad = root.Number("dodge_angle_deg") * kDegToRad;
  p.shoot_kick = root.String("shoot_kick");
  p.aim_tolerance_rad = root.Number("aim_tolerance_deg") * kDegToRad;
  p.gap_padding = root.Number("gap_padding");
  p.regrab_delay_s = root.Number("regrab_delay_s");
  p.in_the_way_m = root.Number("in_the_way_m");
  p.in_the_way_range_m = root.Number("in_the_way_range_m");
  p.step_aside_m = root.Number("step_aside_m");
  p.back_off_release_m = root.Number("back_off_release_m");
  p.support_ahead_m = root.Number("support_ahead_m");
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
      kicks_(&kicks),
      shoot_kick_(RequireKick(kicks, params.shoot_kick, params.file.string(), "shoot_kick")),
      release_after_s_(sim.ball_holding_limit_s - robot.kick_launch_s),
      dribble_speed_mps_(robot.dribble_speed_mps),
      body_radius_m_(robot.body_radius_m),
      contact_m_(robot.body_radius_m + field.ball.radius_m),
      grab_reach_m_(robot.grab_reach_m),
      dt_s_(sim.control_step_s),
      memory_(static_cast<std::size_t>(robots)) {
  assert(static_cast<std::size_t>(robots) <= params.role_regions.size());
  const KickSpec& shoot = kicks.kicks[static_cast<std::size_t>(shoot_kick_)];
  shoot_range_m_ =
      shoot.launch_offset_m + StopDistance(shoot.speed_mps, kicks.rolling_deceleration_mps2);
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
      if (command.kind == CommandKind::kKick || command.kind == CommandKind::kRelease) {
        m.let_go_s = p.time_s;
      }
    } else if (chasing) {
      command = Chase(m, p);
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

RobotCommand ReactiveTeam::Chase(const Memory& m, const Perception& p) const {
  if (p.time_s - m.let_go_s >= params_.regrab_delay_s - 1e-9) {
    RobotCommand get;
    get.kind = CommandKind::kGetBall;
    return get;
  }
  // Follow the ball to where it could be grabbed, without grabbing it yet.
  const Vec2 to_ball = p.p_F_ball - p.pose.p_F;
  const double distance = to_ball.norm();
  const double stop_m = contact_m_ + grab_reach_m_;
  const Vec2 target = distance > stop_m ? Vec2(p.p_F_ball - stop_m * to_ball / distance)
                                        : p.pose.p_F;
  return WalkTowards(p.pose, target, HeadingTowards(p.pose.p_F, p.p_F_ball), dt_s_);
}

const Pose2* ReactiveTeam::OpponentBlocking(const Perception& p, double heading_rad) const {
  const Vec2 ahead = UnitVector(heading_rad);
  for (const Pose2& opponent : p.opponents) {
    const Vec2 to = opponent.p_F - p.p_F_ball;
    if (to.norm() <= params_.dodge_radius_m && to.dot(ahead) > 0.0) return &opponent;
  }
  return nullptr;
}

std::optional<HeadingInterval> ReactiveTeam::Gap(const Perception& p) const {
  std::vector<Pose2> bodies = p.opponents;
  for (std::size_t i = 0; i < p.teammates.size(); ++i) {
    if (static_cast<int>(i) != p.self) bodies.push_back(p.teammates[i]);
  }
  return BestGoalGap(*field_, p.attack_sign, p.p_F_ball, bodies, body_radius_m_);
}

RobotCommand ReactiveTeam::Hold(Memory& m, const Perception& p) const {
  const Vec2 goal(p.attack_sign * field_->HalfLength(), 0.0);
  const double goal_heading = HeadingTowards(p.p_F_ball, goal);
  const double to_line_m = field_->HalfLength() - p.attack_sign * p.p_F_ball.x();
  const bool in_range = to_line_m <= shoot_range_m_;
  const std::optional<HeadingInterval> gap = in_range ? Gap(p) : std::nullopt;
  const double theta = p.pose.theta_rad;
  const double shoot_offset = kicks_->kicks[static_cast<std::size_t>(shoot_kick_)].direction_rad;
  if (p.time_s - m.holding_since_s >= release_after_s_) {
    // The holding limit: the shot only if the gap lies ahead, else let the ball go.
    if (gap && gap->Contains(theta + shoot_offset, 0.0)) return KickCommand(shoot_kick_);
    RobotCommand release;
    release.kind = CommandKind::kRelease;
    return release;
  }
  if (const Pose2* opponent = OpponentBlocking(p, goal_heading)) {
    return Dodge(p, *opponent, goal_heading);
  }
  if (gap) {
    if (gap->Contains(theta + shoot_offset, params_.gap_padding)) return KickCommand(shoot_kick_);
    return TurnTowards(p.pose, gap->Centre() - shoot_offset, dt_s_);
  }
  if (in_range) return DribbleTowards(p, goal_heading);  // the goal is shut: go nearer
  const double aim = goal_heading - shoot_offset;  // the forward kick
  if (std::abs(WrapAngle(aim - theta)) <= params_.aim_tolerance_rad) return KickCommand(shoot_kick_);
  return TurnTowards(p.pose, aim, dt_s_);
}

RobotCommand ReactiveTeam::Dodge(const Perception& p, const Pose2& opponent,
                                 double goal_heading) const {
  // Away from the opponent as seen along the robot's own heading, so that the turn never
  // sweeps the held ball through the opponent standing in the way.
  double side = WrapAngle(HeadingTowards(p.p_F_ball, opponent.p_F) - p.pose.theta_rad);
  // Dead ahead (noiseless scenarios line robots up exactly): dodge towards the middle of the
  // field, where there is room; a rule in field terms, so the mirrored game plays the same.
  if (std::abs(side) < 1e-9) side = SideOf(p.p_F_ball.y()) * p.attack_sign;
  return DribbleTowards(p, goal_heading + (side > 0.0 ? -1.0 : 1.0) * params_.dodge_angle_rad);
}

RobotCommand ReactiveTeam::DribbleTowards(const Perception& p, double heading_rad) const {
  RobotCommand walk;
  walk.kind = CommandKind::kWalk;
  const double error = WrapAngle(heading_rad - p.pose.theta_rad);
  walk.turn_radps = error / dt_s_;
  // Walk on only when roughly facing the way to go; turn on the spot with the ball otherwise.
  if (std::abs(error) < 0.25 * kPi) walk.v_R_mps = Vec2(dribble_speed_mps_, 0.0);
  return walk;
}

RobotCommand ReactiveTeam::Support(Memory& m, const Perception& p, double distance_m) const {
  const Vec2& ball = p.p_F_ball;
  const double face = HeadingTowards(p.pose.p_F, ball);
  const Vec2 goal(p.attack_sign * field_->HalfLength(), 0.0);
  const Vec2 line = goal - ball;
  const double length_m = line.norm();
  const Vec2 along = length_m > 1e-9 ? Vec2(line / length_m) : UnitVector(face);
  const Vec2 normal(-along.y(), along.x());
  const Vec2 rel = p.pose.p_F - ball;
  const double t = rel.dot(along);
  const double offset_m = rel.dot(normal);
  // Level with the line: step towards the middle of the field, as the dodge does.
  const double side = std::abs(offset_m) > kLevelM ? SideOf(offset_m)
                                                   : -SideOf(ball.y()) * SideOf(normal.y());
  // In the way: between ball and goal, near the line (hysteresis: a backing-up lasts until
  // back_off_release_m further out), near enough the ball.
  const double corridor_m = params_.in_the_way_m + (m.backing_up ? params_.back_off_release_m : 0.0);
  m.backing_up = distance_m <= params_.in_the_way_range_m && t > 0.0 && t < length_m &&
                 std::abs(offset_m) < corridor_m;
  const double margin_m = body_radius_m_;
  auto on_field = [&](Vec2 q) {
    q.x() = std::clamp(q.x(), -field_->HalfLength() + margin_m, field_->HalfLength() - margin_m);
    q.y() = std::clamp(q.y(), -field_->HalfWidth() + margin_m, field_->HalfWidth() - margin_m);
    return q;
  };
  if (m.backing_up) {
    RobotCommand back =
        WalkTowards(p.pose, on_field(p.pose.p_F + side * params_.step_aside_m * normal), face, dt_s_);
    back.backing_up = true;
    return back;
  }
  Vec2 target = ball + params_.support_ahead_m * along + side * params_.support_side_m * normal;
  const FieldBox& own = params_.role_regions[static_cast<std::size_t>(p.self)];
  target = (p.attack_sign > 0.0 ? own : own.MirroredX()).Clamp(target);
  return WalkTowards(p.pose, on_field(target), face, dt_s_);
}

}  // namespace foresight
