#include "planner/position_value.h"

#include <algorithm>
#include <cmath>

#include "common/fast_math.h"

namespace foresight {

PositionValue::PositionValue(const PotentialParams& potential, const FieldSpec& field)
    : inverse_linear_x_scale_(1.0 / potential.linear_x_scale_m) {
  for (const GaussianTerm& g : potential.gaussians) {
    terms_.push_back({g.centre_x_m, g.centre_y_m, 1.0 / g.sigma_x_m, 1.0 / g.sigma_y_m, g.weight});
  }
  Vec2 p_min_F, p_max_F;
  GridExtremes(field, &p_min_F, &p_max_F);
  potential_min_ = Refine(field, p_min_F, -1.0);
  potential_max_ = Refine(field, p_max_F, +1.0);
  const double range = potential_max_ - potential_min_;
  value_scale_ = range > 0.0 ? 1.0 / range : 0.0;  // a flat potential values every position 0
}

double PositionValue::Potential(const Vec2& p_F) const {
  double f = -p_F.x() * inverse_linear_x_scale_;
  for (const Term& g : terms_) {
    const double dx = (p_F.x() - g.centre_x_m) * g.inverse_sigma_x;
    const double dy = (p_F.y() - g.centre_y_m) * g.inverse_sigma_y;
    f += g.weight * ExpFast(-0.5 * (dx * dx + dy * dy));
  }
  return f;
}

void PositionValue::PotentialLanes(const Lanes* x, const Lanes* y, Lanes* f, int groups) const {
  for (int i = 0; i < groups; ++i) f[i] = -x[i] * inverse_linear_x_scale_;
  for (const Term& g : terms_) {
    for (int i = 0; i < groups; ++i) {
      const Lanes dx = (x[i] - g.centre_x_m) * g.inverse_sigma_x;
      const Lanes dy = (y[i] - g.centre_y_m) * g.inverse_sigma_y;
      f[i] += g.weight * ExpFastLanes(-0.5 * (dx * dx + dy * dy));
    }
  }
}

namespace {

struct GridBest {
  Vec2 p_F;
  double f;  // sign * potential
};

}  // namespace

// The grid of both extremes in one pass, kLanes points at a time (a decision process builds one
// planner, and this grid was most of its start). Each lane has the scalar Potential's bits and the
// points are compared in the scalar scan's order, so the extremes are those of that scan.
void PositionValue::GridExtremes(const FieldSpec& field, Vec2* p_min_F, Vec2* p_max_F) const {
  const double hx = field.HalfLength(), hy = field.HalfWidth();
  const int nx = static_cast<int>(std::ceil(field.field_length_m / kGridStep_m));
  const int ny = static_cast<int>(std::ceil(field.field_width_m / kGridStep_m));
  const Vec2 corner(-hx, -hy);
  GridBest low{corner, -Potential(corner)}, high{corner, Potential(corner)};
  const int count = (nx + 1) * (ny + 1);
  for (int first = 0; first < count; first += kLanes) {
    Lanes x = Broadcast(-hx), y = Broadcast(-hy);  // padding lanes repeat the corner
    for (int l = 0; l < kLanes && first + l < count; ++l) {
      const int i = (first + l) / (ny + 1), j = (first + l) % (ny + 1);
      x[l] = -hx + field.field_length_m * i / nx;
      y[l] = -hy + field.field_width_m * j / ny;
    }
    const Lanes f = PotentialLanes(x, y);
    for (int l = 0; l < kLanes && first + l < count; ++l) {
      if (-f[l] > low.f) low = {Vec2(x[l], y[l]), -f[l]};
      if (f[l] > high.f) high = {Vec2(x[l], y[l]), f[l]};
    }
  }
  *p_min_F = low.p_F;
  *p_max_F = high.p_F;
}

double PositionValue::Refine(const FieldSpec& field, Vec2 best, double sign) const {
  // Compass search inside the field from the grid's best point, to 1e-6 m.
  const double hx = field.HalfLength(), hy = field.HalfWidth();
  double best_f = sign * Potential(best);
  for (double step = kGridStep_m; step > 1e-6; step *= 0.5) {
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
