// The parameters of the CBR team's multi-robot reasoning (Ros et al. 2009, sec. 4): how many
// robots may retrieve, the positioning strategy of the reuse FSM (Fig. 10), and the timeouts and
// tolerances the paper leaves to the designer. models/cbr/team.json gives each value with its
// source or "assumption: why" (the file is rejected otherwise).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "cbr/ball_race.h"
#include "cbr/kick_race.h"
#include "cbr/pass_timing.h"

namespace foresight {

// Sec. 4.2: dependent (everyone executes once the robot that gets the ball is at its adapted
// position; the paper's choice) or independent (everyone waits until all are at theirs).
enum class Positioning { kDependent, kIndependent };
std::string_view PositioningName(Positioning positioning);
std::optional<Positioning> ParsePositioning(std::string_view name);

struct CbrTeamParams {
  std::filesystem::path file;
  int retrievers = 0;  // k: the robots with the k lowest ids may coordinate (sec. 4.1)
  Positioning positioning = Positioning::kDependent;
  double belief_period_s = 0.0;       // how often a robot reports its beliefs (ball, distance)
  double presence_timeout_s = 0.0;    // a teammate not heard from for this long is not present
  double await_case_timeout_s = 0.0;  // no case or "no case" this long after a cycle began
  double adapt_timeout_s = 0.0;       // ADAPT lasts at most this long, then ABORT
  double execute_timeout_s = 0.0;     // EXECUTE lasts at most this long, then ABORT
  double wait_end_timeout_s = 0.0;    // WAIT END without the coordinator's end: a new cycle
  double no_case_retry_s = 0.0;       // after "no case": the default behaviour this long
  double arrive_tolerance_m = 0.0;    // at an adapted position or target
  double ball_lost_margin_m = 0.0;    // an opponent's body this close to the ball has it
  double pass_seen_m = 0.0;           // the ball this far from the passer: the pass was made
  double keep_close_m = 0.0;          // robots out of the play keep this far from the ball
  // The timing-aware pass check (cbr/pass_timing.h), off in the paper's team. The file gives
  // enabled, reaction_s, samples, time_step_s and min_success; the walking speeds and reach
  // are the match's (set by whoever puts the team on a field).
  PassTimingParams pass_timing;
  // The ball race (cbr/ball_race.h): with ball_race, a cycle starts only when the ball rests (it
  // rolls slower than a robot walks) and the team reaches it first, and the robot that gets the
  // ball in a reused case is the team's fastest to it. The file gives ball_race; the speed,
  // reach and tie are the match's (set by whoever puts the team on a field).
  bool ball_race = false;
  RaceParams race;
  // The kick race (cbr/kick_race.h): with kick_race, a case whose getter would not play the ball
  // away before an opponent reaches it is not reused. The file gives kick_race; the robot's
  // times and speeds are the match's (set by whoever puts the team on a field).
  bool kick_race = false;
  HoldParams hold;

  void Validate() const;
};

// `reference`: a bare name in MODELS/cbr/ ("team") or a path ending in ".json".
CbrTeamParams LoadCbrTeamParams(const std::string& reference,
                                const std::filesystem::path& models_dir);

}  // namespace foresight
