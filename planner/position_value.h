// The value of a ball position: the team strategy of Mellmann & Schlotter, sec. III-D.
//
// The potential f (models/evaluation_params.h; lower is better) is mapped linearly to a value
//   v(x, y) = (f_max - f(x, y)) / (f_max - f_min)  in [0, 1],
// where f_min and f_max are f's extremes over the field (found once, at construction, by a
// grid over the field and a local refinement). Inside the opponent goal v = goal_value
// (v_max), outside the field v = 0; Hypothesis evaluation applies those through the category.
#pragma once

#include <algorithm>
#include <vector>

#include "common/geometry.h"
#include "models/evaluation_params.h"
#include "models/field_spec.h"
#include "planner/lanes.h"

namespace foresight {

class PositionValue {
 public:
  PositionValue(const PotentialParams& potential, const FieldSpec& field);

  double Potential(const Vec2& p_F) const;
  double Value(const Vec2& p_F) const { return ValueOfPotential(Potential(p_F)); }
  double ValueOfPotential(double potential) const {
    // Clamped: a ball may rest just past a line (it is out only once fully over it).
    return std::clamp((potential_max_ - potential) * value_scale_, 0.0, 1.0);
  }

  // The same for kLanes positions at once (planner/lanes.h): each lane has the scalar bits.
  Lanes PotentialLanes(Lanes x, Lanes y) const {
    Lanes f;
    PotentialLanes(&x, &y, &f, 1);
    return f;
  }
  // f[g] = PotentialLanes(x[g], y[g]) for g < groups, the groups' independent work interleaved
  // (one term of every group, then the next term), which keeps the pipeline full.
  void PotentialLanes(const Lanes* x, const Lanes* y, Lanes* f, int groups) const;
  Lanes ValueOfPotentialLanes(Lanes potential) const {
    return Clamp((potential_max_ - potential) * value_scale_, Broadcast(0.0), Broadcast(1.0));
  }

  double potential_min() const { return potential_min_; }
  double potential_max() const { return potential_max_; }

 private:
  // The extremes: a 0.1 m grid over the field finds each basin, a compass search refines it.
  static constexpr double kGridStep_m = 0.1;
  void GridExtremes(const FieldSpec& field, Vec2* p_min_F, Vec2* p_max_F) const;
  double Refine(const FieldSpec& field, Vec2 best, double sign) const;  // sign +1: max, -1: min

  // The potential's terms with their scales inverted once: a product per coordinate instead of a division
  // (a division costs several times a product in lanes). The products round differently from
  // the quotients, alike on every build.
  struct Term {
    double centre_x_m, centre_y_m, inverse_sigma_x, inverse_sigma_y, weight;
  };
  double inverse_linear_x_scale_;
  std::vector<Term> terms_;
  double potential_min_ = 0.0;
  double potential_max_ = 0.0;
  double value_scale_ = 1.0;
};

}  // namespace foresight
