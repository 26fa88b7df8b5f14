// A spatial index on the cases' ball scopes (Ros et al. 2009, sec. 2.4: "case indexing
// techniques can be then used to deal with the search space in large case bases").
//
// A case passes retrieval's first test only if sim_B = exp(-[(dx/tau_x)^2 + (dy/tau_y)^2]) >
// thr_b, i.e. only if the problem ball lies strictly inside the ellipse with radii
// tau * sqrt(-ln thr_b) around the case ball (the scope ellipse itself for thr_b = exp(-1)).
// The index stores each case's bounding box of that ellipse, grown by a relative 1e-9 so that
// rounding never drops a case, in a uniform grid over the boxes' union; a query returns, in
// ascending case order, every case whose box's grid cells contain the ball's cell: a superset of
// the cases that pass the ball filter. Every case it leaves out is rejected with
// kBallOutOfScope by EvaluateCase (tests/cbr/ball_scope_index_test.cc checks this on random
// problems).
//
// Cell size: half the median box side (at least 0.01 m, at most 2048 cells a side), so a case
// sits in about nine cells and a query reads one cell's list: about (1.5 side)^2 / side^2 = 2.3
// times the cases whose box holds the ball, against 4 times with cells of a whole side. Cells
// double while the boxes would fill more than 16 cells a case on average (a few huge scopes). Built
// once from a span of cases (for one defending goal) and thr_b; the index keeps only case indices,
// so it stays valid as long as the cases' order and ball scopes do not change. Balls off the grid
// return the cells at its edge (clamped), so every query is still a superset.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cbr/case.h"

namespace foresight {

class BallScopeIndex {
 public:
  BallScopeIndex() = default;
  BallScopeIndex(std::span<const Case> cases, double thr_ball);

  // Indices of the cases whose ball scope may contain p_F, ascending; a view into the index.
  std::span<const std::uint32_t> Query(const Vec2& p_F) const;

  std::size_t size() const { return size_; }  // the cases it was built from
  double thr_ball() const { return thr_ball_; }
  std::size_t entries() const { return ids_.size(); }  // case-in-cell entries
  int columns() const { return nx_; }
  int rows() const { return ny_; }
  double cell_m() const { return cell_m_; }

 private:
  int Cell(double v, double v0, int n) const;

  std::size_t size_ = 0;
  double thr_ball_ = 0.0;
  double x0_ = 0.0, y0_ = 0.0, cell_m_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> start_;  // cell c's cases: ids_[start_[c] .. start_[c + 1])
  std::vector<std::uint32_t> ids_;
};

}  // namespace foresight
