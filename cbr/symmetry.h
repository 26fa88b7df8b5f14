// The symmetric copies of a case (Ros et al. 2009, sec. 2.4): mirrored in y (same defending
// goal), in x (the other goal) and in both. Positions, targets, turn headings and the ball and
// opponent positions are mirrored; scope radii stay (the ellipses are axis-aligned); a kick that
// sends the ball to the robot's left becomes the matching right kick when the mirror flips
// handedness (mirror_y and mirror_x, not mirror_xy); passes keep their receivers.
#pragma once

#include <map>
#include <string>

#include "cbr/case.h"

namespace foresight {

// Kick name -> its mirror image ("head_kick_left" <-> "head_kick_right"), both directions; a kick
// not listed is its own mirror (forward).
using KickMirrors = std::map<std::string, std::string>;

// The transform equal to applying `a`, then `b` (they commute; each is its own inverse).
CaseTransform ComposeTransforms(CaseTransform a, CaseTransform b);

// `c` mirrored by `t`. The result's transform is c.transform composed with t, its name
// "<source>/<transform>" ("<source>" for kOriginal), so mirroring a copy again may give back
// the hand-written case exactly.
Case MirrorCase(const Case& c, CaseTransform t, const KickMirrors& mirrors);

}  // namespace foresight
