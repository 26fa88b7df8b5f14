#include "cbr/cbr_team.h"

#include <algorithm>
#include <limits>

#include "common/error.h"
#include "models/walk_command.h"

namespace foresight {

namespace {
std::size_t At(int i) {
  return static_cast<std::size_t>(i);
}

// The kicks and passes every robot of the case makes.
int KicksIn(const Case& c) {
  int kicks = 0;
  for (const CaseTeammate& t : c.teammates) {
    for (const CaseAction& a : t.actions) {
      kicks += a.type == ActionType::kKick || a.type == ActionType::kPass;
    }
  }
  return kicks;
}

// Why retrieval gave the team no case: the furthest any case got (cbr/team_counters.h).
void CountNoCase(const RetrievalResult& result, CbrTeamCounters& counters) {
  bool blocked = false, too_far = false;
  for (const CaseEvaluation& e : result.evaluations) {
    if (e.verdict == Verdict::kCandidate) {
      ++counters.no_case_candidates_refused;
      return;
    }
    blocked = blocked || e.verdict == Verdict::kPathBlocked;
    too_far = too_far || e.verdict == Verdict::kTooFar;
  }
  ++(blocked ? counters.no_case_path_blocked
             : too_far ? counters.no_case_too_far : counters.no_case_out_of_scope);
}
}  // namespace

CbrTeam::CbrTeam(const CbrTeamSetup& setup, TeamPolicy& default_behaviour, int robots)
    : setup_(setup), default_(&default_behaviour), robots_(At(robots)) {
  const CbrTeamParams& team = *setup.skills.team;
  const bool race_set = team.race.speed_mps > 0.0 && team.race.reach_m >= 0.0;
  if (team.ball_race && !race_set) {
    throw InputError(team.file.string() +
                     ": ball_race: the race needs the robots' walking speed and reach "
                     "(CbrTeamParams::race), which whoever puts the team on a field sets");
  }
  if (team.kick_race && !(race_set && team.hold.dribble_speed_mps > 0.0 &&
                          team.hold.dribble_turn_radps > 0.0 && team.hold.grab_s >= 0.0 &&
                          team.hold.hold_limit_s >= 0.0 && team.hold.launch_s >= 0.0)) {
    throw InputError(team.file.string() +
                     ": kick_race: the race needs the robots' speeds and times with the ball "
                     "(CbrTeamParams::race and ::hold), which whoever puts the team on a field sets");
  }
  for (Robot& r : robots_) {
    // Until a teammate reports, its distance to the ball is unknown: never the closest.
    r.team.assign(At(robots), TeammateBelief{false, std::numeric_limits<double>::infinity()});
    r.heard_s.assign(At(robots), 0.0);
  }
}

CbrPhase CbrTeam::PhaseOf(int robot) const {
  return robots_[At(robot)].phase;
}

int CbrTeam::CycleOf(int robot) const {
  return robots_[At(robot)].cycle;
}

std::span<const Case> CbrTeam::CasesFor(const Perception& p) const {
  return setup_.cases->Defending(DefendingOf(p));
}

DefendingGoal CbrTeam::DefendingOf(const Perception& p) {
  return p.attack_sign > 0.0 ? DefendingGoal::kCyan : DefendingGoal::kYellow;
}

RobotCommand CbrTeam::Decide(const Perception& p) {
  Robot& r = robots_[At(p.self)];
  defending_ = DefendingOf(p);
  if (!p.busy) r.in_kick = false;
  Account(r, p);
  Hear(r, p);
  RobotCommand command = Act(r, p);
  if (p.holding_ball && !r.was_holding) r.holding_since_s = p.time_s;
  r.was_holding = p.holding_ball;
  const ActionContext& ctx = setup_.skills;
  if (p.holding_ball && !p.busy && p.time_s - r.holding_since_s >= ctx.release_after_s &&
      command.kind != CommandKind::kKick) {
    command = RobotCommand{};
    command.kind = CommandKind::kKick;
    command.kick_index = ctx.release_kick;
  }
  // A kick that starts is told at once: a teammate must not retrieve for the ball it launches.
  const bool kick_starts = p.holding_ball && !p.busy && command.kind == CommandKind::kKick;
  if (kick_starts) r.in_kick = true;
  if (!r.outbox.empty()) {
    command.message = r.outbox.front();
    r.outbox.pop_front();
    r.last_sent_s = p.time_s;
  } else if (!command.message &&
             (kick_starts ||
              p.time_s - r.last_sent_s >= setup_.skills.team->belief_period_s - 1e-9)) {
    command.message = MakeCbrMessage(CbrMessageKind::kBelief, r.cycle, p.p_F_ball,
                                     (p.p_F_ball - p.pose.p_F).norm());
    r.last_sent_s = p.time_s;
  }
  if (command.message && IsCbrMessage(*command.message)) {
    command.message->words[kKickingWord] = r.in_kick ? 1 : 0;
  }
  return command;
}

void CbrTeam::Account(Robot& r, const Perception& p) {
  if (r.last_time_s >= 0.0) {
    const double dt = p.time_s - r.last_time_s;
    counters_.phase_time_s[At(static_cast<int>(r.phase))] += dt;
    if (r.phase == CbrPhase::kIdle) {
      if (OpponentHasBall(p, setup_.skills)) {
        counters_.idle_opponent_on_ball_s += dt;
      } else if (r.ball_speed_mps >= setup_.skills.team->race.speed_mps) {
        counters_.idle_ball_rolling_s += dt;
      }
    }
  }
  r.last_time_s = p.time_s;
  if (r.last_ball_time_s >= 0.0 && p.time_s > r.last_ball_time_s) {
    r.ball_speed_mps = (p.p_F_ball - r.last_ball_F).norm() / (p.time_s - r.last_ball_time_s);
  }
  r.last_ball_F = p.p_F_ball;
  r.last_ball_time_s = p.time_s;
}

void CbrTeam::Hear(Robot& r, const Perception& p) {
  const CbrTeamParams& params = *setup_.skills.team;
  for (const TeamMessage& m : p.inbox) {
    if (m.sender < 0 || m.sender >= static_cast<int>(r.team.size())) continue;
    r.heard_s[At(m.sender)] = m.sent_time_s;
    if (IsCbrMessage(m)) {
      r.team[At(m.sender)].ball_distance_m = m.value;
      r.team[At(m.sender)].kicking = m.words[kKickingWord] != 0;
    }
  }
  for (std::size_t i = 0; i < r.team.size(); ++i) {
    r.team[i].present = p.time_s - r.heard_s[i] <= params.presence_timeout_s;
  }
  r.team[At(p.self)] = {true, (p.p_F_ball - p.pose.p_F).norm(), r.in_kick};
  for (const TeamMessage& m : p.inbox) {
    if (IsCbrMessage(m)) HearProtocol(r, p, m);
  }
}

void CbrTeam::HearProtocol(Robot& r, const Perception& p, const TeamMessage& m) {
  const int cycle = m.words[0];
  if (cycle < r.cycle) return;  // an older cycle's message never revives its case
  const int from = r.play ? r.play->CaseTeammateOf(m.sender) : -1;
  switch (*CbrKind(m)) {
    case CbrMessageKind::kBelief:
      return;
    case CbrMessageKind::kCoordinator:
      if (cycle == r.cycle) return;
      r.cycle = cycle;
      r.coordinator = m.words[1];
      r.play.reset();
      if (r.coordinator == p.self && r.in_kick) {
        // Named while its own kick is in motion (the selector had not heard of it yet): it
        // retrieves nothing for a ball it is kicking away; the team's wait for the case times out
        // and the next cycle starts once the kick is over.
        Enter(r, CbrPhase::kIdle, p.time_s);
        r.idle_until_s = p.time_s;
      } else if (r.coordinator == p.self) {
        Retrieve(r, p);
      } else {
        Enter(r, CbrPhase::kAwaitCase, p.time_s);
      }
      return;
    case CbrMessageKind::kCase:
      if (cycle == r.cycle && r.phase != CbrPhase::kAwaitCase) return;
      if (m.words[1] < 0 || m.words[1] >= static_cast<int>(CasesFor(p).size())) return;
      if (cycle > r.cycle) r.coordinator = m.sender;
      Adopt(r, p, cycle, m.words[1], UnpackRobots(m.words[2]), m.p_F);
      // A robot of the case whose own kick is in motion knows the case is for a ball that leaves.
      if (r.in_kick && r.me >= 0) Abort(r, p, AbortReason::kBallMoved);
      return;
    case CbrMessageKind::kNoCase:
      r.cycle = cycle;
      r.play.reset();
      Enter(r, CbrPhase::kIdle, p.time_s);
      r.idle_until_s = p.time_s + setup_.skills.team->no_case_retry_s;
      return;
    case CbrMessageKind::kArrived:
      if (cycle == r.cycle && from >= 0) r.arrived[At(from)] = true;
      return;
    case CbrMessageKind::kPassed:
      if (cycle == r.cycle && m.words[1] == p.self) ++r.progress.passes_heard;
      return;
    case CbrMessageKind::kDone:
      if (cycle == r.cycle && from >= 0) r.done[At(from)] = true;
      return;
    case CbrMessageKind::kEnd:
    case CbrMessageKind::kAbort:
      if (*CbrKind(m) == CbrMessageKind::kAbort && r.play && cycle == r.cycle) {
        // The case of this cycle, not an older one this robot still has.
        if (m.words[1] == static_cast<int>(AbortReason::kTimeout)) r.timed_out = r.play;
        if (m.words[1] == static_cast<int>(AbortReason::kPathBlocked)) r.blocked.push_back(*r.play);
      }
      r.cycle = cycle;
      r.play.reset();
      Enter(r, CbrPhase::kIdle, p.time_s);
      r.idle_until_s = p.time_s;
      return;
  }
}

void CbrTeam::Enter(Robot& r, CbrPhase phase, double time_s) {
  r.phase = phase;
  r.phase_since_s = time_s;
}

void CbrTeam::Send(Robot& r, const Perception& p, CbrMessageKind kind, int word1, int word2) {
  r.outbox.push_back(MakeCbrMessage(kind, r.cycle, p.p_F_ball, (p.p_F_ball - p.pose.p_F).norm(),
                                    word1, word2));
}

void CbrTeam::StartCycle(Robot& r, const Perception& p) {
  const int coordinator = ChooseCoordinator(r.team, setup_.skills.team->retrievers);
  if (coordinator < 0) return;  // a retriever's report is due: try again next step
  ++r.cycle;
  ++counters_.cycles;
  r.coordinator = coordinator;
  r.play.reset();
  Send(r, p, CbrMessageKind::kCoordinator, coordinator);
  if (coordinator == p.self) {
    Retrieve(r, p);
  } else {
    Enter(r, CbrPhase::kAwaitCase, p.time_s);
  }
}

Problem CbrTeam::PerceivedProblem(const Robot& r, const Perception& p) const {
  Problem problem;
  problem.p_F_ball = p.p_F_ball;
  problem.defending = DefendingOf(p);
  for (std::size_t i = 0; i < r.team.size() && problem.teammates.size() < kMaxTeammates; ++i) {
    if (!r.team[i].present) continue;
    problem.teammates.push_back(
        {static_cast<int>(i) + 1, static_cast<int>(i) == p.self ? p.pose : p.teammates[i]});
  }
  for (const Pose2& o : p.opponents) problem.opponents.push_back(o.p_F);
  return problem;
}

bool CbrTeam::MayStartCycle(const Robot& r, const Perception& p) const {
  const CbrTeamParams& params = *setup_.skills.team;
  if (r.timed_out) return false;
  if (OpponentHasBall(p, setup_.skills)) return false;
  for (const TeammateBelief& mate : r.team) {
    if (mate.present && mate.kicking) return false;  // the ball is about to leave
  }
  if (!params.ball_race) return true;
  return r.ball_speed_mps < params.race.speed_mps &&
         RunBallRace(PerceivedProblem(r, p), params.race).won;
}

void CbrTeam::Retrieve(Robot& r, const Perception& p) {
  const Problem problem = PerceivedProblem(r, p);
  const std::span<const Case> cases = CasesFor(p);
  foresight::Retrieve(cases, problem, *setup_.skills.retrieval, &scratch_);
  const std::optional<Choice> chosen = ChooseCase(cases, problem, r.blocked);
  if (!chosen) {
    ++counters_.no_case;
    CountNoCase(scratch_, counters_);
    Send(r, p, CbrMessageKind::kNoCase);
    Enter(r, CbrPhase::kIdle, p.time_s);
    r.idle_until_s = p.time_s + setup_.skills.team->no_case_retry_s;
    return;
  }
  const Correspondence& match = chosen->correspondence;
  CaseRobots robots{-1, -1, -1, -1};
  for (int i = 0; i < match.count; ++i) {
    robots[At(i)] = problem.teammates[At(match.problem_index[At(i)])].id - 1;
  }
  counters_.CountCase(match.count, KicksIn(cases[At(chosen->case_index)]));
  Send(r, p, CbrMessageKind::kCase, chosen->case_index, PackRobots(robots));
  Adopt(r, p, r.cycle, chosen->case_index, robots, p.p_F_ball);
}

std::optional<CbrTeam::Choice> CbrTeam::ChooseCase(std::span<const Case> cases,
                                                   const Problem& problem,
                                                   std::span<const CasePlay> skip) {
  const CbrTeamParams& team = *setup_.skills.team;
  const RetrievalParams& retrieval = *setup_.skills.retrieval;
  BallRace race;
  if (team.ball_race) {
    race = RunBallRace(problem, team.race);
    if (!race.won) {
      ++counters_.race_lost;
      return std::nullopt;
    }
  }
  for (int index : scratch_.ranking) {
    if (std::any_of(skip.begin(), skip.end(),
                    [&](const CasePlay& play) { return play.case_index == index; })) {
      ++counters_.blocked_skipped;
      continue;
    }
    const CaseEvaluation& e = *scratch_.Find(index);
    const Case& c = cases[At(index)];
    Choice choice{index, e.correspondence};
    const int getter = BallGetter(c);
    if (team.ball_race && getter >= 0 &&
        !TeammateWins(problem, choice.correspondence.problem_index[At(getter)], race, team.race)) {
      // The getter loses the race: the same case with the team's fastest robot getting the ball.
      choice.correspondence = FindCorrespondence(problem, c, retrieval.cost, retrieval.thr_cost_m,
                                                 FixedPair{getter, race.fastest});
      if (!choice.correspondence.feasible) {
        ++counters_.race_skipped;
        continue;
      }
    }
    if (!team.kick_race && !team.pass_timing.enabled) return choice;
    const CaseBallPath path =
        BuildBallPath(problem, c,
                      std::span<const Vec2>(choice.correspondence.adapted_F.data(),
                                            At(choice.correspondence.count)),
                      retrieval);
    if (team.kick_race && !RunKickRace(problem, c, choice.correspondence, getter, path,
                                       *setup_.skills.kicks, team.race, team.hold)
                               .won) {
      ++counters_.kick_race_lost;
      continue;
    }
    if (team.pass_timing.enabled) {
      // The timing-aware check: the best-ranked candidate whose passes are likely to arrive.
      if (PassSuccess(path, problem.opponents, *setup_.skills.kicks, team.pass_timing) <
          team.pass_timing.min_success) {
        ++counters_.timing_rejected;
        continue;
      }
    }
    return choice;
  }
  return std::nullopt;
}

void CbrTeam::Adopt(Robot& r, const Perception& p, int cycle, int case_index,
                    const CaseRobots& robots, const Vec2& p_F_ball) {
  const Case& c = CasesFor(p)[At(case_index)];
  r.play = MakeCasePlay(c, case_index, cycle, p_F_ball, robots, *setup_.skills.retrieval);
  r.cycle = cycle;
  r.me = r.play->CaseTeammateOf(p.self);
  r.progress = ActionProgress{};
  r.arrived = {};
  r.done = {};
  r.sent_arrived = false;
  r.all_done_s = -1.0;
  Enter(r, r.me >= 0 ? CbrPhase::kAdapt : CbrPhase::kWaitEnd, p.time_s);
}

void CbrTeam::Abort(Robot& r, const Perception& p, AbortReason reason) {
  counters_.CountAbort(r.cycle, reason);
  if (reason == AbortReason::kTimeout && r.play) r.timed_out = r.play;
  if (reason == AbortReason::kPathBlocked && r.play) r.blocked.push_back(*r.play);
  Send(r, p, CbrMessageKind::kAbort, static_cast<int>(reason));
  r.play.reset();
  Enter(r, CbrPhase::kIdle, p.time_s);
  r.idle_until_s = p.time_s;
}

RobotCommand CbrTeam::Act(Robot& r, const Perception& p) {
  const CbrTeamParams& params = *setup_.skills.team;
  // Every robot, selector or not, forgets a timed-out case once the situation has changed.
  if (r.timed_out && (p.holding_ball || BallLeftScope(*r.timed_out, p, setup_.skills))) {
    r.timed_out.reset();
  }
  std::erase_if(r.blocked,
                [&](const CasePlay& play) { return BallLeftScope(play, p, setup_.skills); });
  if (r.phase == CbrPhase::kIdle && p.time_s >= r.idle_until_s &&
      Selector(r.team) == p.self && MayStartCycle(r, p)) {
    StartCycle(r, p);
  }
  if (r.phase == CbrPhase::kAwaitCase && p.time_s - r.phase_since_s > params.await_case_timeout_s) {
    Enter(r, CbrPhase::kIdle, p.time_s);
    r.idle_until_s = p.time_s;
  }
  switch (r.phase) {
    case CbrPhase::kIdle:
      return Default(p);
    case CbrPhase::kAwaitCase:
      return AwaitCase(p);
    case CbrPhase::kAdapt:
      return Adapt(r, p);
    case CbrPhase::kExecute:
      return Execute(r, p);
    case CbrPhase::kWaitEnd:
      return WaitEnd(r, p);
  }
  return Default(p);
}

RobotCommand CbrTeam::AwaitCase(const Perception& p) {
  // The coordinator retrieves for the ball where it is: a robot holding it keeps it until the
  // case comes (at most await_case_timeout_s, within the holding rule) instead of kicking it
  // away in the default behaviour.
  RobotCommand command = Default(p);
  if (p.holding_ball && command.kind == CommandKind::kKick) {
    RobotCommand hold;  // stand: kStand
    hold.message = command.message;
    return hold;
  }
  return command;
}

RobotCommand CbrTeam::Adapt(Robot& r, const Perception& p) {
  const ActionContext& ctx = setup_.skills;
  const CasePlay& play = *r.play;
  if (p.time_s - r.phase_since_s > ctx.team->adapt_timeout_s) {
    Abort(r, p, AbortReason::kTimeout);
  } else if (OpponentHasBall(p, ctx)) {
    Abort(r, p, AbortReason::kBallLost);
  } else if (BallLeftScope(play, p, ctx)) {
    Abort(r, p, AbortReason::kBallMoved);
  }
  if (r.phase != CbrPhase::kAdapt) return Default(p);
  const Vec2 target = play.adapted_F[At(r.me)];
  // The getter's adapted position is next to the ball (sec. 4.2): holding it is being there.
  const bool there = (target - p.pose.p_F).norm() <= ctx.team->arrive_tolerance_m ||
                     (r.me == play.getter && p.holding_ball);
  if (there && !r.sent_arrived) {
    r.sent_arrived = true;
    r.arrived[At(r.me)] = true;
    Send(r, p, CbrMessageKind::kArrived);
  }
  bool ready = play.getter >= 0 && r.arrived[At(play.getter)];
  if (ctx.team->positioning == Positioning::kIndependent) {
    for (int i = 0; i < play.TeammateCount(); ++i) ready = ready && r.arrived[At(i)];
  }
  // A lost "arrived" must not stall the team: the getter playing the ball shows it too.
  ready = ready || (p.p_F_ball - play.p_F_ball).norm() > ctx.team->pass_seen_m;
  if (ready) {
    Enter(r, CbrPhase::kExecute, p.time_s);
    return Execute(r, p);
  }
  return WalkTowards(p.pose, target, HeadingTowards(p.pose.p_F, p.p_F_ball),
                     ctx.control_step_s);
}

RobotCommand CbrTeam::Execute(Robot& r, const Perception& p) {
  const ActionContext& ctx = setup_.skills;
  if (p.time_s - r.phase_since_s > ctx.team->execute_timeout_s) {
    Abort(r, p, AbortReason::kTimeout);
    return Default(p);
  }
  const ActionStep step = StepActions(*r.play, r.me, r.progress, p, ctx);
  if (step.abort) {
    Abort(r, p, *step.abort);
    return Default(p);
  }
  if (step.passed_to >= 0) Send(r, p, CbrMessageKind::kPassed, step.passed_to);
  if (step.finished) {
    r.done[At(r.me)] = true;
    Send(r, p, CbrMessageKind::kDone);
    Enter(r, CbrPhase::kWaitEnd, p.time_s);
    return WaitEnd(r, p);
  }
  return step.command;
}

RobotCommand CbrTeam::WaitEnd(Robot& r, const Perception& p) {
  const CbrTeamParams& params = *setup_.skills.team;
  const CasePlay& play = *r.play;
  bool all_done = true;
  for (int i = 0; i < play.TeammateCount(); ++i) all_done = all_done && r.done[At(i)];
  if (all_done && r.all_done_s < 0.0) r.all_done_s = p.time_s;
  double limit_s = params.wait_end_timeout_s + params.execute_timeout_s;
  if (r.me < 0) limit_s += params.adapt_timeout_s;
  const bool ended = all_done && r.coordinator == p.self;
  const bool end_lost = all_done && p.time_s - r.all_done_s > params.wait_end_timeout_s;
  const bool safety_net = p.time_s - r.phase_since_s > limit_s;
  if (ended || end_lost || safety_net) {
    if (ended) {
      Send(r, p, CbrMessageKind::kEnd);
      counters_.CountCompleted(KicksIn(*play.c));
    } else if (safety_net && !all_done && r.me >= 0) {
      ++counters_.wait_end_timeouts;
    }
    r.play.reset();
    Enter(r, CbrPhase::kIdle, p.time_s);
    r.idle_until_s = p.time_s;
    return Default(p);
  }
  // Its DONE again every belief period while it waits: one lost message must not keep the case
  // going until the safety net.
  if (r.me >= 0 && p.time_s - r.last_sent_s >= params.belief_period_s - 1e-9 && r.outbox.empty()) {
    Send(r, p, CbrMessageKind::kDone);
  }
  if (p.holding_ball) return Default(p);
  return KeepClose(p, params.keep_close_m, setup_.skills.control_step_s);
}

RobotCommand CbrTeam::Default(const Perception& p) {
  default_inbox_.clear();
  for (const TeamMessage& m : p.inbox) {
    if (m.kind < kCbrKindBase) default_inbox_.push_back(m);
  }
  default_perception_ = p;  // reuses the member's vectors: no allocation once warm
  default_perception_.inbox = default_inbox_;
  return default_->Decide(default_perception_);
}

std::string CbrTeam::MessageName(const TeamMessage& m) const {
  return CbrKind(m) ? CbrMessageName(m, setup_.cases->Defending(defending_))
                    : default_->MessageName(m);
}

std::vector<TeamPolicy::Counter> CbrTeam::Counters() const {
  return counters_.List();
}

}  // namespace foresight
