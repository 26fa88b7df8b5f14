// Where bodies may stand when a situation or a match starts: on the carpet or the field, clear
// of the goal posts, the ball out of the goals and their nets, bodies apart. Physics would push
// a body out of a post at once (teleporting the ball a metre in no time) and a ball that starts
// in a goal or outside the field ends a match before it begins, so files that place things are
// checked with these (models/situation.h, match/match_config.cc). Messages say "WHAT: position
// (x, y) ..." for the caller to prefix with its file.
#pragma once

#include <string>

#include "common/geometry.h"
#include "models/field_spec.h"

namespace foresight {

// "(x, y)" with the project's number format.
std::string PointText(const Vec2& p);

bool OnCarpet(const FieldSpec& field, const Vec2& p_F);
// "|x| <= L m, |y| <= W m" of the carpet.
std::string CarpetText(const FieldSpec& field);

// Throws unless `p_F` lies on the field, its lines included: "WHAT: (x, y) is off the field".
void RequireOnField(const FieldSpec& field, const std::string& what, const Vec2& p_F);

// A body of radius_m at p_F must not stand in a post.
void RequireClearOfPosts(const FieldSpec& field, const std::string& what, const Vec2& p_F,
                         double radius_m);

// The ball must not start in a goal or in its net: inside the box between the posts' centres
// and the back net, or within its radius of the side and back nets (the coarse model's net
// lines).
void RequireBallOutOfGoals(const FieldSpec& field, const Vec2& p_F);

}  // namespace foresight
