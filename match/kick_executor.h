// How a kick in a match is carried out: through the OutcomeSimulator seam (models/outcome.h), in
// a static scene of the moment the ball leaves: the field and every other robot standing where
// it is as an obstacle. The coarse executor rolls the drawn launch (planner/); a physics
// executor (the command line's --physics, when it exists) would run the Bullet trial instead.
// The match then replays the outcome's path in time, so robots that move while the ball rolls
// can still stop it (match/ball_motion.h).
#pragma once

#include <span>

#include "models/outcome.h"

namespace foresight {

class KickExecutor {
 public:
  virtual ~KickExecutor() = default;
  // Safe to call from several threads at once.
  virtual Outcome Execute(std::span<const Obstacle> robots, const DrawnState& state,
                          const ConcreteAction& action) const = 0;
};

// The coarse model: a CoarseSimulator built for the scene of each kick.
class CoarseKickExecutor final : public KickExecutor {
 public:
  CoarseKickExecutor(const FieldSpec& field, double rolling_deceleration_mps2)
      : field_(&field), deceleration_mps2_(rolling_deceleration_mps2) {}
  Outcome Execute(std::span<const Obstacle> robots, const DrawnState& state,
                  const ConcreteAction& action) const override;

 private:
  const FieldSpec* field_;
  double deceleration_mps2_;
};

}  // namespace foresight
