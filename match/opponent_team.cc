#include "match/opponent_team.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "models/walk_command.h"

namespace foresight {

namespace {
constexpr double kFree = std::numeric_limits<double>::infinity();
// Candidate headings of a turn with the ball are this far apart: finer than any kick's spread.
constexpr double kHeadingStepRad = kPi / 180.0;
}  // namespace

int RequireKick(const KickModel& kicks, const std::string& name, const std::string& file,
                const std::string& field) {
  const std::optional<int> index = kicks.Find(name);
  if (!index) {
    throw InputError(file + ": " + field + ": unknown kick '" + name + "' (the kick model has " +
                     kicks.Names() + ")");
  }
  return *index;
}

OpponentTeam::OpponentTeam(const MatchConfig& config, const FieldSpec& field,
                           const KickModel& kicks, const RobotParams& robot,
                           const SimulationParams& sim)
    : config_(&config),
      kicks_(&kicks),
      contact_m_(robot.body_radius_m + field.ball.radius_m),
      grab_reach_m_(robot.grab_reach_m),
      grab_cone_rad_(robot.grab_cone_rad),
      dt_s_(sim.control_step_s),
      release_after_s_(sim.ball_holding_limit_s - robot.kick_launch_s),
      memory_(config.opponents.size()) {
  const std::string file = config.file.string();
  clear_kicks_.push_back(RequireKick(kicks, config.clear_kick, file, "clear_kick"));
  for (std::size_t i = 0; i < config.clear_side_kicks.size(); ++i) {
    clear_kicks_.push_back(RequireKick(kicks, config.clear_side_kicks[i], file,
                                       "clear_side_kicks[" + std::to_string(i) + "]"));
  }
  for (const OpponentSpec& spec : config.opponents) {
    goalies_.emplace_back(config.goalie, spec.region, field, robot, kicks.rolling_deceleration_mps2,
                          sim.control_step_s);
  }
}

double OpponentTeam::BlockedAt(const Perception& p, double heading_rad) const {
  const Vec2 ahead = UnitVector(heading_rad);
  double nearest_m = kFree;
  auto consider = [&](const Pose2& other) {
    const Vec2 to = other.p_F - p.p_F_ball;
    const double distance = to.norm();
    if (distance >= config_->clear_free_distance_m || distance < 1e-9) return;
    if (std::acos(std::clamp(to.dot(ahead) / distance, -1.0, 1.0)) > config_->clear_free_cone_rad) {
      return;
    }
    nearest_m = std::min(nearest_m, distance);
  };
  for (std::size_t i = 0; i < p.teammates.size(); ++i) {
    if (static_cast<int>(i) != p.self) consider(p.teammates[i]);
  }
  for (const Pose2& o : p.opponents) consider(o);
  return nearest_m;
}

bool OpponentTeam::SafeDirection(const Perception& p, double heading_rad, int kick) const {
  const double upfield_rad = p.attack_sign > 0.0 ? 0.0 : kPi;
  const double sigma_rad = kicks_->kicks[static_cast<std::size_t>(kick)].sigma_direction_rad;
  const double widest_rad = 0.5 * kPi - config_->clear_direction_margin_sd * sigma_rad;
  return std::abs(WrapAngle(heading_rad - upfield_rad)) <= widest_rad;
}

RobotCommand OpponentTeam::Clear(Memory& m, const Perception& p) const {
  const double theta = p.pose.theta_rad;
  auto kick_heading = [&](int kick) {
    return theta + kicks_->kicks[static_cast<std::size_t>(kick)].direction_rad;
  };
  RobotCommand kick;
  kick.kind = CommandKind::kKick;
  const double side_y = p.p_F_ball.y() >= -1e-9 ? 1.0 : -1.0;  // the nearer side line's sign
  // A safe, free kick now: the clear kick first, then the side kicks, the one towards the nearer
  // side line first (a rule in field terms, so the mirrored game kicks the mirrored kick).
  std::vector<int> order = clear_kicks_;
  std::stable_sort(order.begin() + 1, order.end(), [&](int a, int b) {
    return std::sin(kick_heading(a)) * side_y > std::sin(kick_heading(b)) * side_y;
  });
  for (int k : order) {
    if (SafeDirection(p, kick_heading(k), k) && BlockedAt(p, kick_heading(k)) == kFree) {
      kick.kick_index = k;
      return kick;
    }
  }
  if (p.time_s - m.holding_since_s >= release_after_s_) {
    // The rule makes it kick: unblocked before blocked, then the most upfield.
    const double upfield_rad = p.attack_sign > 0.0 ? 0.0 : kPi;
    double best = -kFree;
    for (int k : clear_kicks_) {
      const double score = (BlockedAt(p, kick_heading(k)) == kFree ? 2.0 : 0.0) +
                           std::cos(WrapAngle(kick_heading(k) - upfield_rad));
      if (score > best) {
        best = score;
        kick.kick_index = k;
      }
    }
    return kick;
  }
  // Turn with the ball towards the nearest safe, free heading of the clear kick.
  const int clear = clear_kicks_.front();
  const double clear_dir = kicks_->kicks[static_cast<std::size_t>(clear)].direction_rad;
  double target = p.attack_sign > 0.0 ? 0.0 : kPi;  // upfield when no heading is free
  for (int step = 0; step <= 180; ++step) {
    const double turn = step * kHeadingStepRad;
    double first = theta + clear_dir + turn, second = theta + clear_dir - turn;
    if (std::sin(second) * side_y > std::sin(first) * side_y) std::swap(first, second);
    const double* found = nullptr;
    for (const double* heading : {&first, &second}) {
      if (found == nullptr && SafeDirection(p, *heading, clear) && BlockedAt(p, *heading) == kFree) {
        found = heading;
      }
    }
    if (found != nullptr) {
      target = *found - clear_dir;
      break;
    }
  }
  return TurnTowards(p.pose, target, dt_s_);
}

RobotCommand OpponentTeam::Defend(const Perception& p) const {
  const FieldBox& region = config_->opponents[static_cast<std::size_t>(p.self)].region;
  const Vec2& ball = p.p_F_ball;
  // The ball counts as in the region when the robot can grab it from inside: a ball held one
  // body length outside the boundary would otherwise stay out of play in front of it forever.
  if ((region.Clamp(ball) - ball).norm() > contact_m_ + grab_reach_m_) {
    return WalkTowards(p.pose, region.Clamp(ball), HeadingTowards(p.pose.p_F, ball), dt_s_);
  }
  return GoForBallInRegion(p, region, contact_m_, grab_reach_m_, grab_cone_rad_, dt_s_);
}

RobotCommand OpponentTeam::Decide(const Perception& p) {
  const std::size_t self = static_cast<std::size_t>(p.self);
  Memory& m = memory_[self];
  if (p.holding_ball && !m.was_holding) m.holding_since_s = p.time_s;
  m.was_holding = p.holding_ball;
  if (config_->opponents[self].role == OpponentRole::kGoalie &&
      config_->goalie.model == GoalieModel::kRunswift2005 && !p.holding_ball) {
    return goalies_[self].Decide(p);  // it sees every step, busy or not
  }
  if (p.busy) return {};
  if (p.holding_ball) return Clear(m, p);
  return Defend(p);
}

}  // namespace foresight
