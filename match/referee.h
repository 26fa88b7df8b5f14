// The referee of the passing trials (Ros et al. 2009, sec. 5.1.4 and 5.2.2): watches the ball's
// path one control step at a time and says when and how a trial ends.
//
// The first field line the ball crosses outward decides, as for a kick (models/field_lines.h):
// over the attacked goal line between the posts is a goal; over it within close_margin_m
// outside the goal (|y| <= goal half width + margin where it crosses) is "close" (the paper's
// "passes near one of the goalposts"; the margin is our definition, models/match/simulation.json);
// any other crossing is out. In the 2D configuration a ball that enters the attacked penalty
// area ends the trial as penalty_area ("to goal"). The goalie's touch (block) and the time limit
// are judged by the simulator, which knows who touched the ball.
#pragma once

#include <optional>

#include "match/match_config.h"
#include "match/trial_result.h"
#include "models/field_lines.h"

namespace foresight {

class Referee {
 public:
  // attack_sign +1: the attackers attack the goal at +x.
  Referee(const FieldSpec& field, const SimulationParams& sim, bool penalty_area_ends_trial,
          double attack_sign);

  // The outcome if the ball's move from `from` to `to` during one step ends the trial.
  std::optional<TrialOutcome> Judge(const Vec2& from, const Vec2& to) const;

 private:
  TrialOutcome ClassifyCrossing(const Vec2& from, const Vec2& to) const;

  FieldLines lines_;
  double close_margin_m_;
  FieldBox penalty_area_;
  bool penalty_area_ends_trial_;
  double attack_sign_;
};

}  // namespace foresight
