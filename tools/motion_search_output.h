// What the motion search prints and writes: a line per candidate for the terminal, the whole
// search as JSON (every candidate's figures, the best ones' keyframes and balance), and the best
// candidates as motion files in the shipped format (the start motion's file with its keyframes
// and balance offsets replaced: notes, stance and ball placement as they were).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "tools/motion_search.h"

namespace foresight {

// "r0 c12  score 0.0412  launch 1.102 sd 0.041 m/s  dir -1.3 deg  fell 0/20  missed 0"
std::string CandidateLine(const SearchCandidate& candidate);
// The round's line: how many candidates were scored and refused (by rule), then the best
// `keep` of all rounds so far.
std::string RoundText(int round, const MotionSearchResult& result, int keep);

nlohmann::ordered_json SearchJson(const MotionSearchSettings& settings,
                                  const MotionSearchResult& result);

// The candidate as a motion file: `start_file`'s JSON with keyframes (degrees rounded to
// 1e-4, times to 1e-6 s) and balance offsets replaced.
std::string MotionFileText(const std::filesystem::path& start_file, const KickMotion& motion);

}  // namespace foresight
