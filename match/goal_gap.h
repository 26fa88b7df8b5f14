// The open part of the attacked goal's mouth as seen from the ball, after rUNSWift 2005's shot
// (robot/PyCode/sGrabTurnKick.py, selectGap and performAimToGoal: the robot holding the ball
// spins towards the larger of the two gaps the goalie leaves and shoots when it faces inside it
// with a fifth of the gap's width to spare on either side).
//
// The mouth: the headings from the ball to the posts' inner edges, narrowed by the angle a ball
// radius subtends there (a ball heading along an edge heading would graze the post). Each body
// (centre, radius) that lies between the ball and the goal line hides the headings within
// asin((radius + ball radius) / distance) of its centre's heading. The best gap is the widest
// interval that remains (of two as wide, the one on the ball's side of the field); none when
// bodies hide the whole mouth or the ball is not in front of the goal line.
#pragma once

#include <optional>
#include <span>

#include "common/geometry.h"
#include "models/field_spec.h"

namespace foresight {

// Headings in F, min_rad <= max_rad, not wrapped across +-pi (the attacked goal lies ahead).
struct HeadingInterval {
  double min_rad = 0.0;
  double max_rad = 0.0;

  double Centre() const { return 0.5 * (min_rad + max_rad); }
  double Width() const { return max_rad - min_rad; }
  // heading_rad (any wrapping) lies inside with `padding` (a share of the width) to spare on
  // either side.
  bool Contains(double heading_rad, double padding) const;
};

// attack_sign +1: the goal at +x. body_radius_m: the radius of every body in `bodies`.
std::optional<HeadingInterval> BestGoalGap(const FieldSpec& field, double attack_sign,
                                           const Vec2& p_F_ball, std::span<const Pose2> bodies,
                                           double body_radius_m);

}  // namespace foresight
