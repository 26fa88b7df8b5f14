#include "match/goal_gap.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace foresight {

bool HeadingInterval::Contains(double heading_rad, double padding) const {
  const double spare = padding * Width();
  const double h = Centre() + WrapAngle(heading_rad - Centre());  // unwrapped near the interval
  return h > min_rad + spare && h < max_rad - spare;
}

namespace {

// Two gaps' widths this close are a tie; a ball's y this close to 0 is level (rounding, e.g.
// sin(pi) in the mirrored game, must not decide).
constexpr double kTieRad = 1e-9;
constexpr double kLevelM = 1e-9;

// Headings measured from the attack direction, so the mouth never wraps across +-pi.
double Relative(double heading_rad, double attack_sign) {
  return WrapAngle(heading_rad - (attack_sign > 0.0 ? 0.0 : kPi));
}

}  // namespace

std::optional<HeadingInterval> BestGoalGap(const FieldSpec& field, double attack_sign,
                                           const Vec2& p_F_ball, std::span<const Pose2> bodies,
                                           double body_radius_m) {
  const double line_x = attack_sign * field.HalfLength();
  const double ahead_m = attack_sign * (line_x - p_F_ball.x());
  if (!(ahead_m > 0.0)) return std::nullopt;
  const double ball_m = field.ball.radius_m;
  const double base = attack_sign > 0.0 ? 0.0 : kPi;
  auto edge = [&](double y, double narrow_sign) {
    const Vec2 to = Vec2(line_x, y) - p_F_ball;
    const double graze = std::asin(std::min(1.0, ball_m / to.norm()));
    return Relative(std::atan2(to.y(), to.x()), attack_sign) + narrow_sign * graze;
  };
  // Seen along the attack direction, +y is to the left for +x and to the right for -x.
  const double half = field.goal.InnerHalfWidth();
  const double a = edge(half, attack_sign > 0.0 ? -1.0 : 1.0);
  const double b = edge(-half, attack_sign > 0.0 ? 1.0 : -1.0);
  std::vector<HeadingInterval> open{{std::min(a, b), std::max(a, b)}};
  if (!(open.front().Width() > 0.0)) return std::nullopt;
  for (const Pose2& body : bodies) {
    const Vec2 to = body.p_F - p_F_ball;
    const double along_m = attack_sign * to.x();
    if (!(along_m > 0.0) || along_m > ahead_m + body_radius_m) continue;  // not in the way
    const double distance = to.norm();
    const double reach = body_radius_m + ball_m;
    const double centre = Relative(std::atan2(to.y(), to.x()), attack_sign);
    const double hide = distance > reach ? std::asin(reach / distance) : 0.5 * kPi;
    std::vector<HeadingInterval> rest;
    for (const HeadingInterval& g : open) {
      if (centre - hide > g.min_rad) rest.push_back({g.min_rad, std::min(g.max_rad, centre - hide)});
      if (centre + hide < g.max_rad) rest.push_back({std::max(g.min_rad, centre + hide), g.max_rad});
    }
    open.clear();
    for (const HeadingInterval& g : rest) {
      if (g.Width() > 0.0) open.push_back(g);
    }
  }
  if (open.empty()) return std::nullopt;
  // The widest; of two as wide (a noiseless game lines bodies up exactly), the one on the ball's
  // side of the field (+y when level), so that the mirrored game picks the mirrored gap.
  const double side = p_F_ball.y() >= -kLevelM ? 1.0 : -1.0;
  auto on_side = [&](const HeadingInterval& g) { return g.Centre() * attack_sign * side > 0.0; };
  HeadingInterval best = open.front();
  for (const HeadingInterval& g : open) {
    const double wider = g.Width() - best.Width();
    if (wider > kTieRad || (std::abs(wider) <= kTieRad && on_side(g) && !on_side(best))) best = g;
  }
  return HeadingInterval{base + best.min_rad, base + best.max_rad};
}

}  // namespace foresight
