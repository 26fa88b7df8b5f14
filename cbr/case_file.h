// One hand-written case file (models/cases/*.json) read into a Case (cbr/case.h), strictly.
//
// Format (SI units, frame F: the cyan goal at -x; every key below is required unless marked
// optional, any other key is an error):
//   {
//     "name": "front_pass_dg",              unique in the case base, no '/'; by convention the
//                                           file's name
//     "notes": "what situation it is for",  required here (not just allowed)
//     "defending": "cyan",                  "cyan" | "yellow"
//     "ball": {"x_m": 1.5, "y_m": 0.0},
//     "ball_scope": {"tau_x_m": 0.45, "tau_y_m": 0.25},
//     "teammates": [                        1-4, ids 1..4 distinct; stored by ascending id
//       {"id": 1, "x_m": 1.2, "y_m": 0.0, "actions": [
//         {"type": "get_ball"},
//         {"type": "pass", "kick": "forward", "to": 2},
//         {"type": "receive", "from": 2},
//         {"type": "kick", "kick": "forward", "at": "goal"},      or "target": {"x_m", "y_m"}
//         {"type": "go_to", "target": {"x_m": 1.0, "y_m": 0.5}},
//         {"type": "dribble", "target": {"x_m": 1.0, "y_m": 0.5}},
//         {"type": "turn", "heading_deg": 90},                     or "face": {"x_m", "y_m"}
//         {"type": "wait"}]}],
//     "opponents": [                        optional, 0-4, ids 1..4 distinct
//       {"id": 1, "x_m": 2.0, "y_m": 0.0, "scope": {"tau_x_m": 0.3, "tau_y_m": 0.3}}]
//   }
// Kick names are those of the AIBO kick model; positions and targets lie on the field
// (|x| <= half length, |y| <= half width); scopes are finite and positive.
//
// The gameplay rules (sec. 2.2), as checked here:
//   (i)  exactly one robot starts with get_ball, and get_ball appears nowhere else (our choice:
//        the paper asks for "at least one"; two robots fetching the same ball would break (ii));
//   (ii) a robot controls the ball from its get_ball or receive until its next pass or kick;
//        dribble, pass and kick are only allowed while controlling it. Following the ball from
//        the get_ball robot: a pass to robot r hands control to r, whose next ball action must be
//        receive from the passer; a kick releases the ball for good. Every pass has its receive
//        and every receive its pass; no ball action may lie outside that chain. A gameplay may end
//        with the ball still controlled (e.g. get_ball, dribble). go_to, turn and wait are
//        allowed with or without the ball.
#pragma once

#include <filesystem>

#include "cbr/case.h"
#include "models/field_spec.h"
#include "models/kick_model.h"

namespace foresight {

// What a case is checked against: the field (positions) and the kick model (kick names).
struct CaseRules {
  FieldSpec field;
  KickModel kicks;
};

// Checks a case against the rules above; throws InputError "case NAME: FIELD: problem".
void ValidateCase(const Case& c, const CaseRules& rules);

// Reads and validates one case file; errors read "FILE: case NAME: FIELD: problem".
Case LoadCaseFile(const std::filesystem::path& file, const CaseRules& rules);

}  // namespace foresight
