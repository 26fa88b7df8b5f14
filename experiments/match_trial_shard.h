// One trial of the match simulator (match/trial_result.h) in a shard file (report/shard_file.h,
// everything the passing reports read from a trial (outcome, counters, the team's
// own counters, events and the trace of the recorded trial), doubles written exactly, so that a
// trial read back is the trial that was played, bit for bit.
//
//   {"outcome": 3,
//    "counters": {"opponent_touches": [..], "opponent_kicks": [..], "attacker_backups": [..],
//                 "attacker_kicks": [..], "grabs_failed": 0, "kicks_missed": 0,
//                 "kicks_not_settled": 0, "kicks_fell": 0, "kicks_blocked": 0, "time_s": 12.5,
//                 "last_touch": [side, robot],
//                 "attacker_kick_sent": 0, "shots": [on target, saved]},
//    "team_counters": [["cases_retrieved", 2], ...],
//    "events": [[time_s, kind, side, robot, ball x, ball y, "detail"], ...],
//    "trace": [[time_s, ball x, ball y, [[x, y, theta], ...]], ...]}
//
// The enums are stored by their numbers (checked on reading), like the outcomes of the seam.
// Reading checks every value against what a played trial guarantees (TrialShape): a trace frame
// holds every robot of the scenario, counters are never negative and have one entry per robot of
// their side, a robot index names a robot of its side, times lie within the time limit, positions
// lie within the shape's bounds. So a tampered or truncated shard is refused with its place instead of reaching the
// reports (which index robots by the trace's first frame).
#pragma once

#include <nlohmann/json.hpp>

#include "match/trial_result.h"
#include "report/shard_file.h"

namespace foresight {

// What every trial of one scenario has: its robots of each side (the trace lists the attackers
// first), the last time it may reach (the time limit plus one control step) and how far from the
// field's centre a ball or robot may be (|x| and |y| at most these: robots stay on the carpet,
// and the referee ends a trial within a control step of the ball leaving the field).
struct TrialShape {
  int attackers = 0;
  int opponents = 0;
  double max_time_s = 0.0;
  double max_abs_x_m = 0.0;
  double max_abs_y_m = 0.0;
};

nlohmann::json TrialShardJson(const MatchTrialResult& trial);
// InputError naming the file and the place in it when `value` is not such a trial of `shape`.
MatchTrialResult ReadShardTrial(const ShardValue& value, const TrialShape& shape);

}  // namespace foresight
