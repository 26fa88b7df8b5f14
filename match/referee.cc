#include "match/referee.h"

#include <cmath>

namespace foresight {

Referee::Referee(const FieldSpec& field, const SimulationParams& sim, bool penalty_area_ends_trial,
                 double attack_sign)
    : lines_(FieldLines::Of(field)),
      close_margin_m_(sim.close_margin_m),
      penalty_area_(PenaltyArea(field, sim, attack_sign)),
      penalty_area_ends_trial_(penalty_area_ends_trial),
      attack_sign_(attack_sign) {}

std::optional<TrialOutcome> Referee::Judge(const Vec2& from, const Vec2& to) const {
  const Vec2 step = to - from;
  const double length_m = step.norm();
  if (length_m > 0.0) {
    const Category category = ClassifyPath(lines_, from, step / length_m, length_m);
    if (category != Category::kInfield) return ClassifyCrossing(from, to);
  }
  if (penalty_area_ends_trial_ && penalty_area_.Contains(to) && !penalty_area_.Contains(from)) {
    return TrialOutcome::kPenaltyArea;
  }
  return std::nullopt;
}

TrialOutcome Referee::ClassifyCrossing(const Vec2& from, const Vec2& to) const {
  const Vec2 step = to - from;
  const Category category = ClassifyPath(lines_, from, step.normalized(), step.norm());
  const Category attacked = attack_sign_ > 0.0 ? Category::kOppGoal : Category::kOwnGoal;
  if (category == attacked) return TrialOutcome::kGoal;
  if (category != Category::kOut) return TrialOutcome::kOut;  // into the attackers' own goal
  // Out: close when the path crosses the attacked goal line first, near a post.
  const double x_from = attack_sign_ * from.x();
  const double x_to = attack_sign_ * to.x();
  if (x_to <= lines_.out_x_m || x_from >= lines_.out_x_m) return TrialOutcome::kOut;
  const double t = (lines_.out_x_m - x_from) / (x_to - x_from);
  const double y_cross = from.y() + t * step.y();
  if (std::abs(y_cross) > lines_.out_y_m) return TrialOutcome::kOut;  // over the side line first
  return std::abs(y_cross) <= lines_.goal_half_width_m + close_margin_m_ ? TrialOutcome::kClose
                                                                         : TrialOutcome::kOut;
}

}  // namespace foresight
