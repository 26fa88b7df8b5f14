// How a kick in a match is carried out: through the OutcomeSimulator seam (models/outcome.h), in
// a static scene of the moment the ball leaves: the field and every other robot standing where
// it is. The coarse executor rolls the drawn launch through the field's posts and nets only
// (planner/): the robots are the match's own moving bodies, which the ball meets and rebounds off
// as it is replayed (match/match_world.h). The physics executor (app/passing_physics.h) runs the
// Bullet trial with the robots as obstacles instead. The match then replays the outcome's path in
// time (match/ball_motion.h).
#pragma once

#include <span>

#include "models/outcome.h"
#include "planner/coarse_simulator.h"

namespace foresight {

class KickExecutor {
 public:
  virtual ~KickExecutor() = default;
  // Safe to call from several threads at once.
  virtual Outcome Execute(std::span<const Obstacle> robots, const DrawnState& state,
                          const ConcreteAction& action) const = 0;
};

// The coarse model: a CoarseSimulator of the field (the robots are left to the match).
class CoarseKickExecutor final : public KickExecutor {
 public:
  CoarseKickExecutor(const FieldSpec& field, double rolling_deceleration_mps2);
  Outcome Execute(std::span<const Obstacle> robots, const DrawnState& state,
                  const ConcreteAction& action) const override;

 private:
  CoarseSimulator simulator_;
};

}  // namespace foresight
