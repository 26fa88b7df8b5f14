// The CBR team (Ros et al. 2009, sec. 4): every robot runs the same reasoning on its own
// perception and the messages it got, and the robots agree through messages only
// (cbr/team_messages.h):
//   1. The robot with the lowest id present (cbr/coordination.h) starts a cycle: it names the
//      retriever closest to the ball the coordinator.
//   2. The coordinator retrieves a case for the problem it perceives (cbr/retrieval.h: the ball,
//      the present teammates, the opponents; optionally checked by cbr/pass_timing.h) and sends
//      the case and the correspondence, or
//      "no case": then everyone plays the default behaviour (the reactive team, sec. 5.1.2) for
//      no_case_retry_s before the next cycle.
//   3. Reuse (Fig. 10): the robots of the case ADAPT (walk to their adapted positions; sec. 3.2)
//      and EXECUTE their actions (cbr/case_actions.h) once the robot that gets the ball is at its
//      position (dependent positioning) or once all are (independent); robots not in the case, and
//      those that finished, keep close to the ball without going after it (WAIT END). Each robot
//      reports DONE; when the coordinator has heard all, it sends END and a new cycle begins:
//      "the execution of the case continues until all robots finish their sequences of actions"
//      (sec. 4.2), so a robot that finished waits for its teammates, whose own actions, aborts
//      and execute timeouts end theirs.
//   4. ABORT: a robot of the case that finds it no longer applicable (ball out of the case's
//      scope while adapting or going for it, ball lost, path blocked) or whose state lasted past
//      its timeout tells the team; everyone goes back to step 1.
// Robustness to lost messages (the paper is silent): every waiting state has a timeout, messages
// of older cycles are ignored, a robot that missed the case plays the default behaviour until a
// newer cycle reaches it, and a receiver whose pass message was lost sees the pass happen. A
// robot out of the case waits at most the adapt, execute and wait-end timeouts together; one that
// finished, the execute and wait-end timeouts (a teammate still executing has its own execute
// timeout; the safety net is counted, wait_end_timeouts), and once it knows all done, the
// wait-end timeout for the coordinator's END. At the start every teammate counts as present (the team starts
// together), until presence_timeout_s passes without a message from it.
// Decisions where the paper is silent: a robot holding the ball when it has no action for it
// plays the default behaviour; any robot that has held the ball for release_after_s kicks it
// with release_kick, whatever its state (the league's holding rule binds both teams); and no
// cycle starts while an opponent has the ball (its body touches it): the default behaviour
// fights for it first, since any case would at once be aborted as "ball lost". Nor while a
// teammate's kick is in motion (every CBR message says whether its sender kicks, and a kick that
// starts is told at once): the situation would not be the one the case is played in. A robot
// named coordinator during its own kick retrieves nothing (the team's wait for the case times
// out), one that adopts a case during it aborts it (ball moved), and a robot awaiting the case
// keeps a ball it holds rather than kick it away in the default behaviour. Without these, 576 of
// the 931 "ball moved" aborts of a DG run (seed 1) came 0.5-1 s after the robot's own kick.
// With ball_race (cbr/ball_race.h, models/cbr/team.json) a cycle also waits until the ball
// rests (rolls slower than the robots walk: a ball at walking speed rolls on at most v^2 / 2a,
// inside a case's ball scope) and the team reaches it first; meanwhile, and after an abort for a
// lost ball until then, the default behaviour plays (so a team that has just lost the ball does
// not retrieve a case and abort it again at once). A candidate whose correspondence sends a
// robot for the ball that an opponent beats to it is matched again with the team's fastest robot
// as its getter (sec. 3.2's cost among those matchings, within thr_c) or passed over for the
// next candidate. Without this check the correspondence alone chose the getter, and a robot
// holding the ball could be sent to wait as the receiver while its teammate walked up to "get"
// it; the holding rule then made the holder kick the power kick blind, which in 2D, where a ball
// in the penalty area counts as to goal, scored: 2D scenarios 1-4 at 7.5, 9.5, 28 and 57.5 % to
// goal without the check, 1.5, 8, 0.5 and 18 % with it (200 trials, seed 1).
// After an abort for a timeout no cycle starts while the ball stays in that case's ball scope
// around the ball it was retrieved for, until the deciding robot holds it: the same situation
// would retrieve the same case, which would time out again. The default behaviour plays until the
// ball has moved (no number of its own: the scope is sec. 3.1's). Every robot of the case
// remembers the case from its own abort or the abort message of the same cycle (a robot that
// missed the message, or was not in the case, may retrieve it once more). Without it a case whose getter
// could not reach its adapted position (the defender standing on it at its region's edge) was
// retrieved and timed out every 10 s until the DG trial's 600 s safety cap (DG, seed 1: 3 of 2000
// trials after the cases' holding revision).
// After an abort for a blocked path the coordinator passes over that case (every case so given
// up, e.g. a case and then its mirror image; counted, blocked_skipped) while the ball stays in
// its ball scope around the ball it was retrieved for: the same ball and opponents would
// retrieve it again and block it again at the kick (the retrieval's corridor starts at the ball,
// the kick's at where the turned robot will launch it). Other cases and the default behaviour
// play meanwhile. Without it, about half of the "path blocked" aborts came a step or two after
// their case, the same case retrieved again each time (docs/EXPERIMENTS.md, section E).
#pragma once

#include <array>
#include <deque>
#include <optional>
#include <vector>

#include "cbr/case_actions.h"
#include "cbr/case_base.h"
#include "cbr/coordination.h"
#include "cbr/retrieval.h"
#include "cbr/team_counters.h"

namespace foresight {

struct CbrTeamSetup {
  const CaseBase* cases = nullptr;
  ActionContext skills;  // team, retrieval and kicks parameters, the shared low-level skills
};

class CbrTeam final : public TeamPolicy {
 public:
  // `default_behaviour` plays a robot whenever the team has no case for it (idle, waiting for a
  // case); it sees only the messages of kinds below kCbrKindBase.
  CbrTeam(const CbrTeamSetup& setup, TeamPolicy& default_behaviour, int robots);
  RobotCommand Decide(const Perception& perception) override;
  std::vector<Counter> Counters() const override;
  // "cbr case 12 front_pass_dg/mirror_y", "cbr abort ball_lost", ...; the default behaviour's
  // messages by their kind.
  std::string MessageName(const TeamMessage& message) const override;

  // For tests and reports: where robot `robot` is in the protocol.
  CbrPhase PhaseOf(int robot) const;
  int CycleOf(int robot) const;

 private:
  struct Robot {
    std::vector<TeammateBelief> team;
    std::vector<double> heard_s;
    int cycle = 0;
    int coordinator = -1;
    CbrPhase phase = CbrPhase::kIdle;
    double phase_since_s = 0.0;
    double idle_until_s = 0.0;
    double last_time_s = -1.0;
    double last_sent_s = -1e9;
    std::optional<CasePlay> play;
    int me = -1;  // case teammate index, -1 when not in the case
    ActionProgress progress;
    std::array<bool, kMaxTeammates> arrived{};
    std::array<bool, kMaxTeammates> done{};
    bool sent_arrived = false;
    double all_done_s = -1.0;  // when this robot first knew every robot of the case done
    bool was_holding = false;
    double holding_since_s = 0.0;
    bool in_kick = false;  // its kick motion runs (from the kick command until it is free)
    bool executing_started = false;
    Vec2 last_ball_F{0.0, 0.0};  // the ball a step ago, for its speed
    double last_ball_time_s = -1.0;
    double ball_speed_mps = 0.0;
    std::optional<CasePlay> timed_out;  // the case last given up for a timeout (see above)
    std::vector<CasePlay> blocked;      // cases given up for a blocked path (see above)
    std::deque<TeamMessage> outbox;
  };

  void Account(Robot& r, const Perception& p);
  void Hear(Robot& r, const Perception& p);
  void HearProtocol(Robot& r, const Perception& p, const TeamMessage& m);
  void Enter(Robot& r, CbrPhase phase, double time_s);
  void Send(Robot& r, const Perception& p, CbrMessageKind kind, int word1 = 0, int word2 = 0);
  void StartCycle(Robot& r, const Perception& p);
  void Retrieve(Robot& r, const Perception& p);
  void Adopt(Robot& r, const Perception& p, int cycle, int case_index, const CaseRobots& robots,
             const Vec2& p_F_ball);
  void Abort(Robot& r, const Perception& p, AbortReason reason);
  RobotCommand Act(Robot& r, const Perception& p);
  RobotCommand AwaitCase(const Perception& p);
  RobotCommand Adapt(Robot& r, const Perception& p);
  RobotCommand Execute(Robot& r, const Perception& p);
  RobotCommand WaitEnd(Robot& r, const Perception& p);
  RobotCommand Default(const Perception& p);
  std::span<const Case> CasesFor(const Perception& p) const;
  static DefendingGoal DefendingOf(const Perception& p);
  // The problem robot `r` perceives: the ball, the present teammates, the opponents.
  Problem PerceivedProblem(const Robot& r, const Perception& p) const;
  // Whether a cycle may start now (the ball free, and with ball_race at rest and won).
  bool MayStartCycle(const Robot& r, const Perception& p) const;
  // The case to reuse and its correspondence: the best-ranked candidate (with ball_race, whose
  // getter is the team's fastest robot; with the timing-aware pass check, whose estimated pass
  // success reaches min_success); nullopt for none.
  struct Choice {
    int case_index = -1;
    Correspondence correspondence;
  };
  // `skip`: the cases the team gave up for a blocked path and passes over (see above).
  std::optional<Choice> ChooseCase(std::span<const Case> cases, const Problem& problem,
                                   std::span<const CasePlay> skip);

  CbrTeamSetup setup_;
  TeamPolicy* default_;
  DefendingGoal defending_ = DefendingGoal::kCyan;  // the goal the team defends (for names)
  std::vector<Robot> robots_;
  RetrievalResult scratch_;
  std::vector<TeamMessage> default_inbox_;  // the default behaviour's messages this step
  Perception default_perception_;            // what the default behaviour is shown
  CbrTeamCounters counters_;  // the experimenter's instruments (cbr/team_counters.h)
};

}  // namespace foresight
