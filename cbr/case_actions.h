// One robot's part of a reused case, action by action (Ros et al. 2009, sec. 2.2 and 4.2, state
// EXECUTE of Fig. 10): each action starts when its precondition holds and ends when its effect
// is reached; the robot then reports DONE. The low-level skills (walk, grab, aim, kick) are the
// ones the reactive team uses ("the low level behaviors are equal for both approaches", sec.
// 5.3), so the two teams differ only in their reasoning.
//
//   get_ball: walk to the ball and grab it; done when holding it.
//   pass, kick: hold the ball (get it back if it was lost), turn with it until the kick's
//            direction (models/kick_model.h) points at the planned trajectory's end (the case's
//            ball path from B^p: the receiver's spot, the target or the goal's centre), kick;
//            done when the kick is over. A kick that would break the ball-holding rule is made
//            at once, aimed or not. A pass reports itself to its receiver.
//            Under pressure (an opponent closing in while the robot aims) the reuse layer keeps
//            its case and aims the short way round; it does not hand the ball to the reactive
//            dodge (match/reactive_team.h), which walks it 45 degrees off the line away from
//            the opponent, away from the case's aim: the case is the plan. The case is given up
//            when the ball is lost or the opponent stands on its path (path_blocked).
//   receive: until the pass is made, walk on to the adapted position facing the ball (under
//            dependent positioning the robot may not be there yet), unless an earlier action of
//            its own moved it, and there face the ball; the pass is made: the passer's message,
//            or, should the message be lost, the ball seen pass_seen_m away from the passer
//            after it had it, or, for the first pass, away from both the passer and where the
//            case found it. Then get the ball; done when holding it.
//   go_to, dribble: walk (with the ball for dribble) to the adapted target; done within
//            arrive_tolerance_m. A dribble also ends early enough to aim the kick or pass that
//            follows it before the holding rule forces the ball away: when the time the robot
//            may still hold the ball is what turning with the ball to that aim takes (at
//            dribble_turn_radps) plus one control step, so that a dribble longer than the holding
//            time allows ends in an aimed kick rather than the holding rule's unaimed one.
//   turn:    turn on the spot to the heading or to face the adapted point.
//   wait:    done at once (the receive that follows it waits for the pass itself).
// The case is no longer applicable, and the robot aborts, when (checked while it is in charge of
// the ball): an opponent touches the ball (ball_lost: OpponentHasBall); while the robot that gets
// the ball first goes for it, the ball left the case's ball scope around B^p (ball_moved: sim_B
// <= thr_b, sec. 3.1; the team checks the same while adapting); an
// opponent stands on the trajectory it is about to kick (path_blocked: the free-path test of
// sec. 3.3.1 on that trajectory, from where the ball will leave: the held ball sits at the
// robot's front and turns with it, so from the robot's centre along the heading it aims at).
#pragma once

#include <cstddef>
#include <optional>

#include "cbr/case_play.h"
#include "cbr/team_params.h"
#include "models/kick_model.h"
#include "models/team_policy.h"

namespace foresight {

// What the actions need besides the case: the team's parameters and the shared skills.
struct ActionContext {
  const CbrTeamParams* team = nullptr;
  const RetrievalParams* retrieval = nullptr;
  const KickModel* kicks = nullptr;
  double aim_tolerance_rad = 0.0;  // the reactive team's (models/match/reactive.json)
  double dribble_turn_radps = 0.0; // how fast a robot holding the ball turns (the match's robot)
  double release_after_s = 0.0;    // kick once the ball was held this long (holding rule)
  int release_kick = kNoKick;      // ... with this kick (the reactive team's shoot kick)
  double control_step_s = 0.0;
};

// One robot's progress through its action sequence.
struct ActionProgress {
  std::size_t action = 0;
  int kicks_done = 0;  // its kicks and passes so far (the n-th is its n-th trajectory)
  bool kicking = false;
  bool was_holding = false;
  double holding_since_s = 0.0;
  int passes_heard = 0;   // passes to this robot its messages announced (in this case)
  int receives_done = 0;  // its receive actions completed
  bool passer_had_ball = false;  // receive: the ball was seen at the passer
};

struct ActionStep {
  RobotCommand command;
  bool finished = false;
  std::optional<AbortReason> abort;
  int passed_to = -1;  // a pass just left: the receiver's robot index
};

// The command of robot `me` (case teammate index) for this step.
ActionStep StepActions(const CasePlay& play, int me, ActionProgress& progress,
                       const Perception& perception, const ActionContext& ctx);

// Before the case's first kick the ball must stay in the case's ball scope around B^p.
bool BallLeftScope(const CasePlay& play, const Perception& perception, const ActionContext& ctx);

// Out of play: stay keep_close_m from the ball on the robot's side of it, facing it (sec. 4.2).
RobotCommand KeepClose(const Perception& perception, double keep_close_m, double dt_s);

// Whether the ball is lost: an opponent's body touches the perceived ball, even while a teammate
// holds it or fights for it. Decision: a case assumes a free ball; in a fight the default
// behaviour (the reactive team's dodge) takes over until the ball is free again. Tried the
// other way (not lost while a teammate is nearer to the ball than the opponent): with the
// shipped kicks the fights then lasted, DG scenario 1 went from 0 to 46 % timeouts and the
// defender's touches per trial from 9 to 29 (300 trials, seed 1).
bool OpponentHasBall(const Perception& perception, const ActionContext& ctx);

}  // namespace foresight
