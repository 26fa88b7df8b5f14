#include "cbr/ball_scope_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"

namespace foresight {
namespace {

struct Box {
  double x_min, x_max, y_min, y_max;
};

}  // namespace

BallScopeIndex::BallScopeIndex(std::span<const Case> cases, double thr_ball)
    : size_(cases.size()), thr_ball_(thr_ball) {
  if (!(thr_ball > 0.0 && thr_ball < 1.0)) {
    throw InputError("BallScopeIndex: thr_ball must lie in (0, 1)");
  }
  if (cases.size() >= std::numeric_limits<std::uint32_t>::max()) {
    throw InputError("BallScopeIndex: too many cases");
  }
  if (cases.empty()) return;
  const double k = std::sqrt(-std::log(thr_ball)) * (1.0 + 1e-9);
  std::vector<Box> boxes;
  boxes.reserve(cases.size());
  std::vector<double> sides;
  sides.reserve(2 * cases.size());
  Box all{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const Case& c : cases) {
    const double rx = k * std::abs(c.ball_scope.tau_x_m) + 1e-12;
    const double ry = k * std::abs(c.ball_scope.tau_y_m) + 1e-12;
    const Box b{c.p_F_ball.x() - rx, c.p_F_ball.x() + rx, c.p_F_ball.y() - ry, c.p_F_ball.y() + ry};
    boxes.push_back(b);
    sides.push_back(2.0 * rx);
    sides.push_back(2.0 * ry);
    all.x_min = std::min(all.x_min, b.x_min);
    all.x_max = std::max(all.x_max, b.x_max);
    all.y_min = std::min(all.y_min, b.y_min);
    all.y_max = std::max(all.y_max, b.y_max);
  }
  std::nth_element(sides.begin(), sides.begin() + static_cast<std::ptrdiff_t>(sides.size() / 2),
                   sides.end());
  cell_m_ = std::max(0.01, 0.5 * sides[sides.size() / 2]);
  if (!std::isfinite(cell_m_) || !std::isfinite(all.x_max - all.x_min) ||
      !std::isfinite(all.y_max - all.y_min)) {
    throw InputError("BallScopeIndex: a case's ball or scope is not finite");
  }
  // At most 2048 cells a side (a wide case base gets coarser cells).
  cell_m_ = std::max({cell_m_, (all.x_max - all.x_min) / 2048.0, (all.y_max - all.y_min) / 2048.0});
  x0_ = all.x_min;
  y0_ = all.y_min;
  // Coarser cells while the boxes would fill more than 16 cells a case on average (a few huge
  // scopes among small ones): memory stays O(cases).
  for (;;) {
    nx_ = std::max(1, static_cast<int>(std::ceil((all.x_max - all.x_min) / cell_m_)));
    ny_ = std::max(1, static_cast<int>(std::ceil((all.y_max - all.y_min) / cell_m_)));
    double entries = 0.0;
    for (const Box& b : boxes) {
      entries += (Cell(b.x_max, x0_, nx_) - Cell(b.x_min, x0_, nx_) + 1.0) *
                 (Cell(b.y_max, y0_, ny_) - Cell(b.y_min, y0_, ny_) + 1.0);
    }
    if (entries <= 16.0 * static_cast<double>(boxes.size()) + 4096.0 || (nx_ == 1 && ny_ == 1)) {
      break;
    }
    cell_m_ *= 2.0;
  }
  const auto cell_x = [&](double x) { return Cell(x, x0_, nx_); };
  const auto cell_y = [&](double y) { return Cell(y, y0_, ny_); };
  // Two passes (count, then fill): compressed rows, each cell's cases ascending.
  const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  start_.assign(cells + 1, 0);
  for (const Box& b : boxes) {
    for (int iy = cell_y(b.y_min); iy <= cell_y(b.y_max); ++iy) {
      for (int ix = cell_x(b.x_min); ix <= cell_x(b.x_max); ++ix) {
        ++start_[static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx_) +
                 static_cast<std::size_t>(ix) + 1];
      }
    }
  }
  for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  ids_.resize(start_[cells]);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Box& b = boxes[i];
    for (int iy = cell_y(b.y_min); iy <= cell_y(b.y_max); ++iy) {
      for (int ix = cell_x(b.x_min); ix <= cell_x(b.x_max); ++ix) {
        ids_[fill[static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx_) +
                  static_cast<std::size_t>(ix)]++] = static_cast<std::uint32_t>(i);
      }
    }
  }
}

int BallScopeIndex::Cell(double v, double v0, int n) const {
  // Clamped as a double first: a far ball must not overflow the int.
  const double c = std::clamp(std::floor((v - v0) / cell_m_), 0.0, static_cast<double>(n - 1));
  return static_cast<int>(c);
}

std::span<const std::uint32_t> BallScopeIndex::Query(const Vec2& p_F) const {
  if (nx_ == 0 || !std::isfinite(p_F.x()) || !std::isfinite(p_F.y())) return {};
  const int ix = Cell(p_F.x(), x0_, nx_);
  const int iy = Cell(p_F.y(), y0_, ny_);
  const std::size_t c =
      static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(ix);
  return {ids_.data() + start_[c], ids_.data() + start_[c + 1]};
}

}  // namespace foresight
