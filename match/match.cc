#include "match/match.h"

#include <algorithm>
#include <cmath>

#include "common/random.h"
#include "match/match_world.h"
#include "match/referee.h"
#include "match/robot_collisions.h"
#include "match/robot_motion.h"
#include "models/walk_command.h"

namespace foresight {

namespace {

class Match {
 public:
  Match(const MatchSetup& setup, const Scenario& scenario, TeamPolicy& attackers,
        TeamPolicy& opponents, std::uint64_t trial_key)
      : s_(setup),
        rng_(trial_key),
        trial_key_(trial_key),
        referee_(*setup.field, *setup.sim, setup.config->penalty_area_ends_trial,
                 setup.attack_sign),
        policies_{&attackers, &opponents},
        contact_m_(setup.robot->body_radius_m + setup.field->ball.radius_m),
        field_world_(CoarseWorld::Build(Scene{setup.field, {},
                                              setup.kicks->rolling_deceleration_mps2,
                                              CoarseRebounds{}})) {
    AddRobots(Side::kAttackers, scenario.attackers);
    AddRobots(Side::kOpponents, scenario.opponents);
    world_.ball.p_F = scenario.p_F_ball;
    rules_.x_max_m = setup.field->CarpetHalfLength() - setup.robot->body_radius_m;
    rules_.y_max_m = setup.field->CarpetHalfWidth() - setup.robot->body_radius_m;
    rules_.body_radius_m = setup.robot->body_radius_m;
    rules_.contact_m = contact_m_;
    for (const RobotState& r : world_.robots) {
      rules_.regions.push_back(
          r.side == Side::kOpponents
              ? std::optional<FieldBox>(
                    setup.config->opponents[static_cast<std::size_t>(r.index)].region)
              : std::nullopt);
    }
    result_.counters.attacker_backups.assign(scenario.attackers.size(), 0);
    result_.counters.attacker_kicks.assign(scenario.attackers.size(), 0);
    result_.counters.opponent_touches.assign(scenario.opponents.size(), 0);
    result_.counters.opponent_kicks.assign(scenario.opponents.size(), 0);
  }

  MatchTrialResult Run() {
    const double dt = s_.sim->control_step_s;
    // Step count instead of accumulated time, so every trial sees the same clock.
    const long max_steps = std::lround(s_.config->time_limit_s / dt);
    Record();
    for (long step = 1; step <= max_steps; ++step) {
      const Vec2 ball_before = world_.ball.p_F;
      DeliverMessages();
      std::vector<RobotCommand> commands = Decide();
      world_.time_s = static_cast<double>(step) * dt;
      Act(commands);
      const std::vector<int> met = StepBall(world_, BallParams());
      const std::optional<TrialOutcome> touched_end = UpdateTouches(met);
      EndKickTravel(met);
      UpdateContest();
      UpdateGameStuck();
      std::optional<TrialOutcome> end = referee_.Judge(ball_before, world_.ball.p_F);
      if (!end) end = touched_end;
      if (world_.time_s >= next_trace_s_ || end) Record();
      if (end) return Finish(*end);
    }
    return Finish(TrialOutcome::kTimeout);
  }

 private:
  void AddRobots(Side side, const std::vector<Pose2>& poses) {
    for (std::size_t i = 0; i < poses.size(); ++i) {
      RobotState robot;
      robot.side = side;
      robot.index = static_cast<int>(i);
      robot.pose = poses[i];
      world_.robots.push_back(robot);
    }
  }

  void Event(EventKind kind, int robot, std::string detail = {}) {
    const RobotState& r = world_.robots[static_cast<std::size_t>(robot)];
    result_.events.push_back({world_.time_s, kind, r.side, r.index, world_.ball.p_F, detail});
  }

  void Record() {
    if (!(s_.trace_period_s > 0.0)) return;
    TraceFrame frame{world_.time_s, world_.ball.p_F, {}};
    for (const RobotState& r : world_.robots) frame.robots.push_back(r.pose);
    result_.trace.push_back(std::move(frame));
    next_trace_s_ = world_.time_s + s_.trace_period_s - 1e-9;
  }

  BallStepParams BallParams() const {
    return {contact_m_, s_.sim->control_step_s, s_.sim->touch_tolerance_m, s_.robot_restitution,
            &field_world_};
  }

  // The kick in flight ends its own travel once the ball rests, meets a body or is held.
  void EndKickTravel(const std::vector<int>& met) {
    if (kick_in_flight_ < 0) return;
    const char* how = world_.ball.holder >= 0 ? "grab"
                      : !met.empty()           ? "body"
                      : !world_.ball.roll      ? "rest"
                                               : nullptr;
    if (how == nullptr) return;
    Event(EventKind::kKickEnd, kick_in_flight_, how);
    kick_in_flight_ = -1;
    shot_on_target_ = false;
  }

  // Robot `robot` touched, grabbed or kicked the ball.
  void NoteTouch(int robot) {
    const RobotState& r = world_.robots[static_cast<std::size_t>(robot)];
    result_.counters.last_touch_side = static_cast<int>(r.side);
    result_.counters.last_touch_robot = r.index;
    if (r.side == Side::kOpponents) result_.counters.attacker_kick_sent = false;
  }

  MatchTrialResult Finish(TrialOutcome outcome) {
    if (kick_in_flight_ >= 0) Event(EventKind::kKickEnd, kick_in_flight_, "end");
    result_.outcome = outcome;
    result_.counters.time_s = world_.time_s;
    result_.events.push_back({world_.time_s, EventKind::kEnd, Side::kAttackers, 0, world_.ball.p_F,
                              std::string(TrialOutcomeName(outcome))});
    return std::move(result_);
  }

  Vec2 Noisy(const Vec2& p, double sigma) {
    if (!(sigma > 0.0)) return p;
    const double nx = rng_.NextNormal();
    const double ny = rng_.NextNormal();
    return p + sigma * Vec2(nx, ny);
  }

  void DeliverMessages() {
    for (RobotState& r : world_.robots) r.inbox.clear();
    std::vector<MessageInFlight> waiting;
    for (const MessageInFlight& m : world_.messages) {
      if (m.deliver_at_s > world_.time_s + 1e-9) {
        waiting.push_back(m);
        continue;
      }
      for (RobotState& r : world_.robots) {
        if (r.side != m.side || r.index == m.message.sender) continue;
        r.inbox.push_back(m.message);
      }
    }
    world_.messages = std::move(waiting);
  }

  Perception Perceive(int robot) {
    const RobotState& me = world_.robots[static_cast<std::size_t>(robot)];
    Perception p;
    p.time_s = world_.time_s;
    p.self = me.index;
    p.pose = me.pose;
    p.holding_ball = world_.ball.holder == robot;
    p.busy = me.activity != Activity::kFree;
    p.p_F_ball = Noisy(world_.ball.p_F, s_.sim->ball_noise_sigma_m);
    world_.robots[static_cast<std::size_t>(robot)].seen_ball = p.p_F_ball;
    for (std::size_t i = 0; i < world_.robots.size(); ++i) {
      const RobotState& r = world_.robots[i];
      Pose2 seen = r.pose;
      if (static_cast<int>(i) != robot) seen.p_F = Noisy(r.pose.p_F, s_.sim->robot_noise_sigma_m);
      (r.side == me.side ? p.teammates : p.opponents).push_back(seen);
    }
    p.attack_sign = me.side == Side::kAttackers ? s_.attack_sign : -s_.attack_sign;
    p.inbox = me.inbox;
    return p;
  }

  std::vector<RobotCommand> Decide() {
    std::vector<RobotCommand> commands;
    for (std::size_t i = 0; i < world_.robots.size(); ++i) {
      RobotState& r = world_.robots[i];
      if (Penalized(r)) {  // it stands at the touchline; its team does not decide for it
        r.backing_up = false;
        commands.emplace_back();
        continue;
      }
      RobotCommand c =
          policies_[r.side == Side::kAttackers ? 0 : 1]->Decide(Perceive(static_cast<int>(i)));
      if (c.message) Send(static_cast<int>(i), *c.message);
      if (r.side == Side::kAttackers && c.backing_up && !r.backing_up) {
        ++result_.counters.attacker_backups[static_cast<std::size_t>(r.index)];
        Event(EventKind::kBackUp, static_cast<int>(i));
      }
      r.backing_up = c.backing_up;
      commands.push_back(c);
    }
    return commands;
  }

  void Send(int robot, TeamMessage message) {
    const RobotState& r = world_.robots[static_cast<std::size_t>(robot)];
    message.sender = r.index;
    message.sent_time_s = world_.time_s;
    const std::string name = policies_[r.side == Side::kAttackers ? 0 : 1]->MessageName(message);
    if (s_.sim->message_loss_rate > 0.0 && rng_.NextUniform() < s_.sim->message_loss_rate) {
      Event(EventKind::kMessageLost, robot, name);
      return;
    }
    world_.messages.push_back({world_.time_s + s_.sim->message_latency_s, r.side, message});
    Event(EventKind::kMessage, robot, name);
  }

  bool InGrabReach(const RobotState& r) const {
    const double distance = (world_.ball.p_F - r.pose.p_F).norm();
    return distance <= contact_m_ + s_.robot->grab_reach_m &&
           std::abs(BearingTo(r.pose, world_.ball.p_F)) <= s_.robot->grab_cone_rad;
  }

  void Act(const std::vector<RobotCommand>& commands);
  void FinishActivity(int robot);
  void Launch(int robot);
  Pose2 Propose(int robot, const RobotCommand& command);
  std::optional<TrialOutcome> UpdateTouches(const std::vector<int>& met);
  bool Contested() const;
  void UpdateContest();
  void UpdateGameStuck();
  void Penalize(int robot);
  Pose2 PenaltyPose(int robot) const;
  bool Penalized(const RobotState& r) const { return world_.time_s < r.penalized_until_s; }
  std::optional<Vec2> FreeSpotNear(const Vec2& p_F) const;
  void UpdateBlock(RobotState& r) const;
  bool InStealCone(const RobotState& challenger, int holder) const;

  const MatchSetup& s_;
  RandomStream rng_;
  std::uint64_t trial_key_;
  Referee referee_;
  TeamPolicy* policies_[2];
  double contact_m_;  // robot centre to ball centre when they touch
  CoarseWorld field_world_;  // posts and nets, for a ball rebounding off a robot
  MoveRules rules_;
  MatchWorld world_;
  MatchTrialResult result_;
  double next_trace_s_ = 0.0;
  int last_toucher_ = -1;  // the robot that began the last counted touch
  int kick_in_flight_ = -1;  // the kicker whose kick's travel has not ended yet
  bool shot_on_target_ = false;  // that kick is an attacker's shot on target
  double contested_since_s_ = -1.0;  // < 0: the ball is not fought over
  Vec2 stuck_ref_F_{0.0, 0.0};       // where the ball lay when it was last seen to move
  double stuck_since_s_ = -1.0;      // < 0: no reference yet
};

void Match::Act(const std::vector<RobotCommand>& commands) {
  std::vector<Pose2> proposed;
  for (std::size_t i = 0; i < world_.robots.size(); ++i) {
    RobotState& r = world_.robots[i];
    if (r.activity == Activity::kKicking && r.kick_index != kNoKick &&
        world_.time_s >= r.launch_at_s - 1e-9) {
      if (world_.ball.holder == static_cast<int>(i)) Launch(static_cast<int>(i));
      r.kick_index = kNoKick;  // the ball has left (or was taken away): the motion runs out
    }
    if (r.activity != Activity::kFree && world_.time_s >= r.busy_until_s - 1e-9) {
      FinishActivity(static_cast<int>(i));
    }
    if (r.activity == Activity::kBlocking) UpdateBlock(r);
    proposed.push_back(r.activity == Activity::kFree ? Propose(static_cast<int>(i), commands[i])
                                                     : r.pose);
  }
  ResolveMoves(world_, rules_, proposed);
}

Pose2 Match::Propose(int robot, const RobotCommand& command) {
  RobotState& r = world_.robots[static_cast<std::size_t>(robot)];
  const RobotParams& rp = *s_.robot;
  const double dt = s_.sim->control_step_s;
  const bool holding = world_.ball.holder == robot;
  const WalkLimits limits =
      holding ? WalkLimits{rp.dribble_speed_mps, rp.dribble_turn_speed_radps,
                           rp.dribble_sideways_mps, rp.dribble_backward_mps}
              : WalkLimits{rp.walk_speed_mps, rp.turn_speed_radps, rp.walk_sideways_mps,
                           rp.walk_backward_mps};
  switch (command.kind) {
    case CommandKind::kStand:
      return r.pose;
    case CommandKind::kWalk:
      return ApplyWalk(r.pose, command.v_R_mps, command.turn_radps, limits, dt);
    case CommandKind::kKick:
      if (holding && command.kick_index >= 0 &&
          command.kick_index < static_cast<int>(s_.kicks->kicks.size())) {
        r.activity = Activity::kKicking;
        r.kick_index = command.kick_index;
        r.launch_at_s = world_.time_s + rp.kick_launch_s;
        r.busy_until_s = world_.time_s + rp.kick_time_s;
      }
      return r.pose;
    case CommandKind::kRelease:
      if (holding) {
        world_.ball.holder = -1;  // it lies where it was held, at the robot's front, at rest
        world_.ball.roll.reset();
        Event(EventKind::kRelease, robot);
      }
      return r.pose;
    case CommandKind::kBlock:
      if (!holding) {
        r.activity = Activity::kBlocking;
        r.block_since_s = world_.time_s;
        r.busy_until_s = world_.time_s + rp.block_down_s + rp.block_hold_s + rp.block_recover_s;
        UpdateBlock(r);
      }
      return r.pose;
    case CommandKind::kGetBall: {
      if (holding) return r.pose;
      if (InGrabReach(r)) {
        r.activity = Activity::kGrabbing;
        r.busy_until_s = world_.time_s + rp.grab_time_s;
        return r.pose;
      }
      // The robot walks to where it sees the ball; whether it can grab is physics (the truth).
      const Vec2 to_ball = r.seen_ball - r.pose.p_F;
      const double distance = to_ball.norm();
      const double stop_m = contact_m_ + 0.5 * rp.grab_reach_m;
      const Vec2 target =
          distance > stop_m ? Vec2(r.seen_ball - stop_m * to_ball / distance) : r.pose.p_F;
      const RobotCommand walk =
          WalkTowards(r.pose, target, HeadingTowards(r.pose.p_F, r.seen_ball), dt);
      return ApplyWalk(r.pose, walk.v_R_mps, walk.turn_radps, limits, dt);
    }
  }
  return r.pose;
}

void Match::FinishActivity(int robot) {
  RobotState& r = world_.robots[static_cast<std::size_t>(robot)];
  const Activity done = r.activity;
  r.activity = Activity::kFree;
  r.block_half_span_m = 0.0;
  if (done != Activity::kGrabbing) return;
  // A grab: the ball must still lie within reach (it may have rolled on or been taken away).
  if (world_.ball.holder == robot || !InGrabReach(r)) return;
  if (rng_.NextUniform() < s_.robot->grab_failure_rate) {
    ++result_.counters.grabs_failed;
    Event(EventKind::kGrabFailed, robot);
    return;
  }
  const int previous = world_.ball.holder;
  // A held ball lies under the holder's chin: only a robot in front of the holder reaches it.
  if (previous >= 0 && !InStealCone(r, previous)) {
    Event(EventKind::kGrabFailed, robot, "covered");
    return;
  }
  // Taking a held ball is a fight between two robots (sec. 5.3.1): it succeeds only so often.
  if (previous >= 0 && rng_.NextUniform() >= s_.robot->steal_success_rate) {
    Event(EventKind::kGrabFailed, robot, "steal");
    return;
  }
  world_.ball.holder = robot;
  world_.ball.roll.reset();
  NoteTouch(robot);
  Event(previous >= 0 ? EventKind::kSteal : EventKind::kGrab, robot);
}

bool Match::InStealCone(const RobotState& challenger, int holder) const {
  const Pose2& h = world_.robots[static_cast<std::size_t>(holder)].pose;
  return std::abs(BearingTo(h, challenger.pose.p_F)) <= s_.robot->steal_cone_rad;
}

// A block spreads the body linearly over block_down_s (from its contact reach to the block's),
// holds it block_hold_s, and is a disc again while the robot gets up.
void Match::UpdateBlock(RobotState& r) const {
  const RobotParams& rp = *s_.robot;
  const double since_s = world_.time_s - r.block_since_s;
  if (since_s > rp.block_down_s + rp.block_hold_s + 1e-9) {
    r.block_half_span_m = 0.0;
    return;
  }
  const double down = rp.block_down_s > 0.0 ? std::min(1.0, since_s / rp.block_down_s) : 1.0;
  r.block_half_span_m = contact_m_ + down * (rp.block_half_span_m - contact_m_);
}

void Match::Launch(int robot) {
  RobotState& r = world_.robots[static_cast<std::size_t>(robot)];
  const KickSpec& kick = s_.kicks->kicks[static_cast<std::size_t>(r.kick_index)];
  std::vector<Obstacle> others;
  for (std::size_t i = 0; i < world_.robots.size(); ++i) {
    if (static_cast<int>(i) != robot) {
      others.push_back({world_.robots[i].pose.p_F, s_.robot->body_radius_m});
    }
  }
  const std::uint64_t stream =
      StreamKey(trial_key_, static_cast<std::uint64_t>(world_.kicks_made++), kMatchKickDomain);
  RandomStream draw(stream);
  ConcreteAction action;
  action.kick_index = r.kick_index;
  action.launch_speed_mps =
      std::max(0.0, kick.speed_mps + kick.sigma_speed_mps * draw.NextNormal());
  action.launch_direction_rad = kick.direction_rad + kick.sigma_direction_rad * draw.NextNormal();
  action.stream = draw.NextBits();
  const Outcome outcome = s_.executor->Execute(others, DrawnState{r.pose, world_.ball.p_F}, action);
  result_.counters.kicks_missed += outcome.status == OutcomeStatus::kMissed;
  result_.counters.kicks_not_settled += outcome.status == OutcomeStatus::kNotSettled;
  result_.counters.kicks_fell += outcome.status == OutcomeStatus::kFell;
  result_.counters.kicks_blocked += outcome.status == OutcomeStatus::kBlocked;
  world_.ball.holder = -1;
  world_.ball.roll = RollFromOutcome(world_.ball.p_F, outcome, s_.kicks->rolling_deceleration_mps2);
  world_.ball.leaving_kicker = robot;
  last_toucher_ = -1;  // a kick ends a possession: the next touch counts, whoever makes it
  NoteTouch(robot);
  result_.counters.attacker_kick_sent = r.side == Side::kAttackers;
  const Category attacked = s_.attack_sign > 0.0 ? Category::kOppGoal : Category::kOwnGoal;
  shot_on_target_ = r.side == Side::kAttackers && outcome.category == attacked;
  result_.counters.shots_on_target += shot_on_target_;
  if (kick_in_flight_ >= 0) Event(EventKind::kKickEnd, kick_in_flight_, "kick");
  kick_in_flight_ = robot;
  auto& kicks = r.side == Side::kAttackers ? result_.counters.attacker_kicks
                                           : result_.counters.opponent_kicks;
  ++kicks[static_cast<std::size_t>(r.index)];
  Event(EventKind::kKick, robot, kick.name);
}

std::optional<TrialOutcome> Match::UpdateTouches(const std::vector<int>& met) {
  std::optional<TrialOutcome> end;
  for (std::size_t i = 0; i < world_.robots.size(); ++i) {
    RobotState& r = world_.robots[i];
    const int robot = static_cast<int>(i);
    const bool touching =
        world_.ball.holder == robot || std::find(met.begin(), met.end(), robot) != met.end() ||
        (robot != world_.ball.leaving_kicker &&
         (world_.ball.p_F - r.pose.p_F).norm() <= contact_m_ + s_.sim->touch_tolerance_m);
    // A touch is a contact that begins while another robot (or none) touched the ball last, so
    // a robot jostling a ball it already has counts once (the paper's possession: how often an
    // opponent "touched or kicked the ball").
    if (touching) NoteTouch(robot);
    if (touching && !r.touching && last_toucher_ != robot) {
      last_toucher_ = robot;
      Event(EventKind::kTouch, robot);
      if (r.side == Side::kOpponents) {
        ++result_.counters.opponent_touches[static_cast<std::size_t>(r.index)];
        if (s_.config->opponents[static_cast<std::size_t>(r.index)].role == OpponentRole::kGoalie) {
          end = TrialOutcome::kBlock;
          result_.counters.shots_saved += shot_on_target_ && kick_in_flight_ >= 0;
        }
      }
    }
    r.touching = touching;
  }
  return end;
}

// Fought over: within grabbing reach of a robot of each team (held, rolling or at rest).
bool Match::Contested() const {
  const double reach_m = contact_m_ + s_.robot->grab_reach_m;
  bool near[2] = {false, false};
  for (const RobotState& r : world_.robots) {
    if ((world_.ball.p_F - r.pose.p_F).norm() <= reach_m + 1e-9) {
      near[static_cast<int>(r.side)] = true;
    }
  }
  return near[0] && near[1];
}

// The referee's rule: a contest begins when a robot holds the ball within reach of the other
// team, and lasts while both teams stay within reach (through steals, releases and kicks into
// the other body). Once it has lasted longer than a robot may hold the ball and the ball is held
// or at rest, the ball is set down at the nearest spot clear of every body, free. A holder that
// kicks the ball away at its holding limit ends the contest itself.
void Match::UpdateContest() {
  if (!Contested()) {
    contested_since_s_ = -1.0;
    return;
  }
  if (contested_since_s_ < 0.0) {
    if (world_.ball.holder < 0) return;
    contested_since_s_ = world_.time_s;
  }
  if (world_.time_s - contested_since_s_ <= s_.sim->ball_holding_limit_s + 1e-9) return;
  if (world_.ball.roll) return;  // a kick on its way: it may yet leave the contest
  const std::optional<Vec2> spot = FreeSpotNear(world_.ball.p_F);
  if (!spot) return;  // no free spot on the whole field: the contest goes on
  world_.ball.holder = -1;
  world_.ball.roll.reset();
  world_.ball.leaving_kicker = -1;
  world_.ball.p_F = *spot;
  ++result_.counters.contests_resolved;
  result_.events.push_back({world_.time_s, EventKind::kBallMoved, Side::kAttackers, 0,
                            world_.ball.p_F, "contest"});
  contested_since_s_ = -1.0;
}

// The league's local game stuck (models/match/simulation.json, stuck_*): once the ball has stayed
// within stuck_ball_still_m of where it lay for stuck_after_s, the robot closest to it (from its
// body's edge, if within stuck_proximity_m) is penalised; the ball's reference is then taken
// anew. With nobody that close the call waits for the first robot that comes close.
void Match::UpdateGameStuck() {
  const SimulationParams& sim = *s_.sim;
  if (stuck_since_s_ < 0.0 || (world_.ball.p_F - stuck_ref_F_).norm() > sim.stuck_ball_still_m) {
    stuck_ref_F_ = world_.ball.p_F;
    stuck_since_s_ = world_.time_s;
    return;
  }
  if (world_.time_s - stuck_since_s_ < sim.stuck_after_s - 1e-9) return;
  int closest = -1;  // ties: the first robot (attackers first)
  double closest_m = 0.0;
  for (std::size_t i = 0; i < world_.robots.size(); ++i) {
    const RobotState& r = world_.robots[i];
    const double edge_m = (world_.ball.p_F - r.pose.p_F).norm() - s_.robot->body_radius_m;
    if (!Penalized(r) && edge_m <= sim.stuck_proximity_m + 1e-9 &&
        (closest < 0 || edge_m < closest_m)) {
      closest = static_cast<int>(i);
      closest_m = edge_m;
    }
  }
  if (closest < 0) return;
  Penalize(closest);
  stuck_since_s_ = -1.0;
}

// A penalised robot lets go of the ball, stops what it was doing and stands at its penalty spot
// for stuck_penalty_s, facing the field.
void Match::Penalize(int robot) {
  RobotState& r = world_.robots[static_cast<std::size_t>(robot)];
  if (world_.ball.holder == robot) {
    world_.ball.holder = -1;
    world_.ball.roll.reset();
  }
  r.activity = Activity::kFree;
  r.kick_index = kNoKick;
  r.block_half_span_m = 0.0;
  r.pose = PenaltyPose(robot);
  r.penalized_until_s = world_.time_s + s_.sim->stuck_penalty_s;
  ++result_.counters.stuck_penalties;
  Event(EventKind::kPenalized, robot, "local_game_stuck");
}

// The carpet's edge next to the touchline on the robot's side, at the height of the front line
// of its own penalty area, or the nearest spot a body's width apart (alternately towards the
// halfway line and the goal line, within the own half) where no other robot stands.
Pose2 Match::PenaltyPose(int robot) const {
  const RobotState& r = world_.robots[static_cast<std::size_t>(robot)];
  const double body_m = s_.robot->body_radius_m;
  const double own_sign = r.side == Side::kAttackers ? -s_.attack_sign : s_.attack_sign;
  const double y = std::copysign(rules_.y_max_m, r.pose.p_F.y() != 0.0 ? r.pose.p_F.y() : 1.0);
  const double heading = y > 0.0 ? -0.5 * kPi : 0.5 * kPi;
  const double x0 = own_sign * (s_.field->HalfLength() - s_.sim->penalty_area_depth_m);
  const int spots = static_cast<int>(std::ceil(2.0 * s_.field->HalfLength() / (2.0 * body_m)));
  for (int k = 0; k <= 2 * spots; ++k) {
    const int step = (k + 1) / 2 * (k % 2 == 1 ? -1 : 1);  // 0, towards halfway, towards goal...
    const Vec2 q(x0 + own_sign * step * 2.0 * body_m, y);
    if (own_sign * q.x() < 0.0 || std::abs(q.x()) > s_.field->HalfLength()) continue;
    bool free = true;
    for (std::size_t j = 0; j < world_.robots.size(); ++j) {
      free = free && (static_cast<int>(j) == robot ||
                      (world_.robots[j].pose.p_F - q).norm() >= 2.0 * body_m);
    }
    if (free) return {q, heading};
  }
  return {Vec2(x0, y), heading};
}

// The nearest point to p_F on rings kSpotStepM apart (kSpotAngles points each, the first one
// upfield of the attackers, then alternately to either side) that lies inside the field lines and
// contest_clearance_m clear of every body.
std::optional<Vec2> Match::FreeSpotNear(const Vec2& p_F) const {
  constexpr double kSpotStepM = 0.02;
  constexpr int kSpotAngles = 72;
  const double ball_m = s_.field->ball.radius_m;
  const double x_max = s_.field->HalfLength() - ball_m;
  const double y_max = s_.field->HalfWidth() - ball_m;
  const double clear_m = contact_m_ + s_.sim->contest_clearance_m;
  const double start_rad = s_.attack_sign > 0.0 ? 0.0 : kPi;
  const int rings = static_cast<int>(std::ceil(2.0 * (x_max + y_max) / kSpotStepM));
  for (int ring = 1; ring <= rings; ++ring) {
    for (int k = 0; k < kSpotAngles; ++k) {
      // 0, +step, -step, +2 step, ...: the two sides of the field alike (counted from the attack
      // direction, so the mirrored game tries the mirrored spots in the same order).
      const int turn = (k + 1) / 2 * (k % 2 == 1 ? 1 : -1);
      const double heading = start_rad + s_.attack_sign * turn * (2.0 * kPi / kSpotAngles);
      const Vec2 q = p_F + ring * kSpotStepM * UnitVector(heading);
      if (std::abs(q.x()) > x_max || std::abs(q.y()) > y_max) continue;
      bool clear = true;
      for (const RobotState& r : world_.robots) clear = clear && (q - r.pose.p_F).norm() >= clear_m;
      if (clear) return q;
    }
  }
  return std::nullopt;
}

}  // namespace

MatchTrialResult RunTrial(const MatchSetup& setup, const Scenario& scenario, TeamPolicy& attackers,
                          TeamPolicy& opponents, std::uint64_t trial_key) {
  MatchTrialResult result = Match(setup, scenario, attackers, opponents, trial_key).Run();
  result.attacker_counters = attackers.Counters();
  return result;
}

}  // namespace foresight
