// What the motion search prints and writes: a line per candidate for the terminal, the whole
// search as JSON (every candidate's figures, the best ones' keyframes and balance), and the best
// candidates as motion files in the shipped format (the start motion's file with the motion's
// figures written over it, notes as they were).
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

// `motion` as a motion file in the layout of `template_file` (a motion file: the start motion of
// a search, the file a mirror replaces): its notes and key order kept, every figure of the
// motion written over it (name, ball spot, the stance's pose, the shift's offsets, joints and
// keyframes; degrees rounded to 1e-4, times to 1e-6 s).
std::string MotionFileText(const std::filesystem::path& template_file, const KickMotion& motion);

}  // namespace foresight
