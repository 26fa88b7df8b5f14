// Planar geometry in the field frame F (origin at the centre spot, x towards the opponent goal,
// y to the left, REP-103) and the robot frame R (x forward, y left). Metres and radians.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/fast_math.h"

namespace foresight {

using Vec2 = Eigen::Vector2d;

// A robot's pose in F: position (m) and heading theta (rad, counter-clockwise from +x).
struct Pose2 {
  Vec2 p_F{0.0, 0.0};
  double theta_rad = 0.0;

  // Maps a point given in this pose's frame into F.
  Vec2 ToField(const Vec2& p_R) const {
    double s, c;
    SinCos(theta_rad, &s, &c);
    return p_F + Vec2(c * p_R.x() - s * p_R.y(), s * p_R.x() + c * p_R.y());
  }
};

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDegToRad = kPi / 180.0;
inline constexpr double kRadToDeg = 180.0 / kPi;

// Wraps an angle into [-pi, pi).
inline double WrapAngle(double angle_rad) {
  double wrapped = std::fmod(angle_rad + kPi, 2.0 * kPi);
  if (wrapped < 0.0) wrapped += 2.0 * kPi;
  return wrapped - kPi;
}

inline Vec2 UnitVector(double angle_rad) {
  double s, c;
  SinCos(angle_rad, &s, &c);
  return Vec2(c, s);
}

// Distance from p to the segment from a along the unit vector dir, length_m long.
inline double DistanceToSegment(const Vec2& p, const Vec2& a, const Vec2& dir, double length_m) {
  const double along = std::clamp((p - a).dot(dir), 0.0, length_m);
  return (a + along * dir - p).norm();
}

}  // namespace foresight
