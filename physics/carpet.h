// The carpet's rolling resistance, applied to a Bullet ball as a central force.
//
// A ball rolling without slipping under a horizontal central force F (opposite to its velocity)
// and the carpet's static friction f obeys  m dv/dt = -F + f,  I dw/dt = -f r,  v = w r, so
//   dv/dt = -F / (m (1 + k)),  k = I / (m r^2)   (k = 2/5 for a solid sphere).
// F = (1 + k) m a therefore decelerates it at exactly a and keeps it on its line at every
// heading. Bullet's own rolling friction on a btRigidBody bends the path when the ball rolls off
// the world axes (bullet3 issue #2117), which is why it is not used.
//
// The resistance acts only while the ball rolls: a ball that slides (just kicked, or after a
// bounce) is slowed by Coulomb friction at its contact point instead, which also spins it up
// until it rolls at v / (1 + k) (k from the field's ball).
//
// a varies: by a factor per trial (the day's carpet, wear) and by a factor per square patch of
// carpet (a fixed layout drawn from the patch seed). docs/ARCHITECTURE.md, "One physics trial".
#pragma once

#include "common/geometry.h"
#include "models/physics_params.h"

class btRigidBody;

namespace foresight {

class BulletWorld;

// Adds the carpet, the plane z = 0 with the carpet's restitution and friction, to a world: the
// one place a world gets its carpet (the trials' scene, the settled stance, the tests).
void AddCarpetPlane(BulletWorld& world, const MaterialParams& materials);

class Carpet {
 public:
  Carpet(const CarpetParams& params, double trial_factor);

  // The deceleration of a freely rolling ball at p_F.
  double DecelerationAt(const Vec2& p_F) const;
  // Applies this step's resisting force to `ball` if it rolls on the carpet (the force is
  // capped so it stops the ball within the step instead of pushing it backwards).
  void ApplyRollingResistance(btRigidBody& ball, double radius_m, double dt_s) const;

 private:
  CarpetParams params_;
  double trial_factor_;
};

// Whether a ball of this radius whose centre is at height z_m touches the carpet.
inline bool TouchesCarpet(double z_m, double radius_m) {
  return z_m < radius_m + 1e-3;
}

// Whether a ball moving at speed_mps whose contact point slips at slip_mps rolls freely: the
// slip is below 1 % of its speed or 1 cm/s (the solver never makes it exactly 0). A kick's
// launch is read once this holds.
inline bool IsRolling(double slip_mps, double speed_mps) {
  constexpr double kSlipShare = 0.01, kSlipFloorMps = 0.01;
  return slip_mps < kSlipFloorMps || slip_mps < kSlipShare * speed_mps;
}

// Whether it clearly slides (just kicked or bounced): the slip is at least 10 % of its speed and
// 2 cm/s. The rolling resistance acts unless it slides: a rolling ball's slip flickers above
// IsRolling's bound for a step now and then on the 16 ms step, and each such step without
// resistance made AIBO balls roll 20 % too far (measured in the calibration's deceleration fit).
inline bool IsSliding(double slip_mps, double speed_mps) {
  constexpr double kSlipShare = 0.1, kSlipFloorMps = 0.02;
  return slip_mps >= kSlipFloorMps && slip_mps >= kSlipShare * speed_mps;
}

}  // namespace foresight
