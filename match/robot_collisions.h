// How the robots' moves of one control step are made physical (match/match.h, step 3): robots
// are discs that never overlap, stay on the carpet, and opponents stay in their home regions.
// Robots move one after the other against where the others stand now. A move into another body
// slides along it (the part towards the other robot is removed); a move that still overlaps a
// body (or pushes a held ball into one), leaves the carpet or leaves an opponent's region is
// cancelled: the robot only turns, or stays as it was if turning is what collides. An opponent
// outside its region (placed at the touchline by a penalty) may only move closer to it. No two bodies
// ever overlap, so the order matters only when two robots meet.
#pragma once

#include <optional>
#include <vector>

#include "match/match_config.h"
#include "match/match_world.h"

namespace foresight {

struct MoveRules {
  double x_max_m = 0.0;  // |x| of a robot's centre at most (the carpet minus the body)
  double y_max_m = 0.0;
  double body_radius_m = 0.0;
  double contact_m = 0.0;                        // robot centre to ball centre when they touch
  std::vector<std::optional<FieldBox>> regions;  // per robot: its home region, if it has one
};

// Whether robot `robot` may stand at `pose` given where the others stand.
bool MoveAllowed(const MatchWorld& world, const MoveRules& rules, std::size_t robot,
                 const Pose2& pose);

// Moves every robot to its proposed pose, or as near as the rules allow.
void ResolveMoves(MatchWorld& world, const MoveRules& rules, const std::vector<Pose2>& proposed);

}  // namespace foresight
