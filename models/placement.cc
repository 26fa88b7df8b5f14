#include "models/placement.h"

#include <cmath>
#include <vector>

#include "common/checks.h"
#include "common/error.h"

namespace foresight {

namespace {

// The four posts' centres.
std::vector<Vec2> PostCentres(const GoalSpec& g) {
  return {Vec2(g.post_centre_x_m, g.post_centre_y_m), Vec2(g.post_centre_x_m, -g.post_centre_y_m),
          Vec2(-g.post_centre_x_m, g.post_centre_y_m),
          Vec2(-g.post_centre_x_m, -g.post_centre_y_m)};
}

}  // namespace

std::string PointText(const Vec2& p) {
  return "(" + FormatNumber(p.x()) + ", " + FormatNumber(p.y()) + ")";
}

bool OnCarpet(const FieldSpec& field, const Vec2& p_F) {
  return std::abs(p_F.x()) <= field.CarpetHalfLength() &&
         std::abs(p_F.y()) <= field.CarpetHalfWidth();
}

std::string CarpetText(const FieldSpec& field) {
  return "|x| <= " + FormatNumber(field.CarpetHalfLength()) +
         " m, |y| <= " + FormatNumber(field.CarpetHalfWidth()) + " m";
}

void RequireOnField(const FieldSpec& field, const std::string& what, const Vec2& p_F) {
  if (!(std::abs(p_F.x()) <= field.HalfLength() && std::abs(p_F.y()) <= field.HalfWidth())) {
    throw InputError(what + ": " + PointText(p_F) + " is off the field (|x| <= " +
                     FormatNumber(field.HalfLength()) + " m, |y| <= " +
                     FormatNumber(field.HalfWidth()) + " m)");
  }
}

void RequireClearOfPosts(const FieldSpec& field, const std::string& what, const Vec2& p_F,
                         double radius_m) {
  for (const Vec2& post : PostCentres(field.goal)) {
    if ((p_F - post).norm() < field.goal.post_radius_m + radius_m) {
      throw InputError(what + ": position " + PointText(p_F) + " overlaps the goal post at " +
                       PointText(post));
    }
  }
}

void RequireBallOutOfGoals(const FieldSpec& field, const Vec2& p_F) {
  const GoalSpec& g = field.goal;
  const double r = field.ball.radius_m;
  const double ax = std::abs(p_F.x()), ay = std::abs(p_F.y());
  const double back_x = g.post_centre_x_m + g.net_depth_m;
  const bool beside_goal = ax > g.post_centre_x_m - r && ax < back_x + r;
  if (ax > g.post_centre_x_m && ax < back_x && ay < g.post_centre_y_m) {
    throw InputError("ball: position " + PointText(p_F) + " lies inside a goal");
  }
  if ((beside_goal && std::abs(ay - g.post_centre_y_m) < r) ||
      (ay < g.post_centre_y_m + r && std::abs(ax - back_x) < r)) {
    throw InputError("ball: position " + PointText(p_F) + " overlaps a goal's net");
  }
}

}  // namespace foresight
