// A joint motor that obeys its DC motor's torque-speed line (models/motor_table.h). Bullet's
// btMultiBodyJointMotor aims at a joint speed with one symmetric impulse bound; this one bounds
// each step's impulse by the torques the motor can give at the joint's speed as the step
// predicts it before the motors act (gravity and other forces of the step applied): along the
// motion tau_stall (1 - w / w0), against it the stall torque. A free joint so
// tends to w0 and never passes it; a loaded one settles where the line meets the load.
#pragma once

#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>

#include "models/motor_table.h"

namespace foresight {

class LineLimitedJointMotor : public btMultiBodyJointMotor {
 public:
  LineLimitedJointMotor(btMultiBody* body, int link, const MotorLine& line);

  void createConstraintRows(btMultiBodyConstraintArray& constraint_rows,
                            btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;

  // The torque the motor applied in the last step (N m, signed like the joint's axis), and the
  // joint speed its bounds were set from.
  double AppliedTorqueNm() const;
  double BoundSpeedRadps() const { return bound_speed_radps_; }
  const MotorLine& line() const { return line_; }

 private:
  MotorLine line_;
  double bound_speed_radps_ = 0.0;
  double step_s_ = 0.0;
};

}  // namespace foresight
