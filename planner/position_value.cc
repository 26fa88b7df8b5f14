#include "planner/position_value.h"

#include <algorithm>
#include <cmath>

#include "common/fast_math.h"

namespace foresight {

PositionValue::PositionValue(const PotentialParams& potential, const FieldSpec& field)
    : potential_(potential) {
  potential_min_ = Extreme(field, -1.0);
  potential_max_ = Extreme(field, +1.0);
  const double range = potential_max_ - potential_min_;
  value_scale_ = range > 0.0 ? 1.0 / range : 0.0;  // a flat potential values every position 0
}

double PositionValue::Potential(const Vec2& p_F) const {
  double f = -p_F.x() / potential_.linear_x_scale_m;
  for (const GaussianTerm& g : potential_.gaussians) {
    const double dx = (p_F.x() - g.centre_x_m) / g.sigma_x_m;
    const double dy = (p_F.y() - g.centre_y_m) / g.sigma_y_m;
    f += g.weight * ExpFast(-0.5 * (dx * dx + dy * dy));
  }
  return f;
}

Lanes PositionValue::PotentialLanes(Lanes x, Lanes y) const {
  Lanes f = -x / potential_.linear_x_scale_m;
  for (const GaussianTerm& g : potential_.gaussians) {
    const Lanes dx = (x - g.centre_x_m) / g.sigma_x_m;
    const Lanes dy = (y - g.centre_y_m) / g.sigma_y_m;
    f += g.weight * ExpFastLanes(-0.5 * (dx * dx + dy * dy));
  }
  return f;
}

double PositionValue::Extreme(const FieldSpec& field, double sign) const {
  // A 0.1 m grid finds the basin; compass search inside the field then refines it to 1e-6 m.
  const double hx = field.HalfLength(), hy = field.HalfWidth();
  const int nx = static_cast<int>(std::ceil(field.field_length_m / 0.1));
  const int ny = static_cast<int>(std::ceil(field.field_width_m / 0.1));
  Vec2 best(-hx, -hy);
  double best_f = sign * Potential(best);
  for (int i = 0; i <= nx; ++i) {
    for (int j = 0; j <= ny; ++j) {
      const Vec2 p(-hx + field.field_length_m * i / nx, -hy + field.field_width_m * j / ny);
      const double f = sign * Potential(p);
      if (f > best_f) best_f = f, best = p;
    }
  }
  for (double step = 0.1; step > 1e-6; step *= 0.5) {
    bool moved = true;
    while (moved) {
      moved = false;
      for (const Vec2& d : {Vec2(step, 0), Vec2(-step, 0), Vec2(0, step), Vec2(0, -step)}) {
        const Vec2 p(std::clamp(best.x() + d.x(), -hx, hx), std::clamp(best.y() + d.y(), -hy, hy));
        const double f = sign * Potential(p);
        if (f > best_f) best_f = f, best = p, moved = true;
      }
    }
  }
  return sign * best_f;
}

}  // namespace foresight
