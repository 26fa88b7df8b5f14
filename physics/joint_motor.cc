#include "physics/joint_motor.h"

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace foresight {

LineLimitedJointMotor::LineLimitedJointMotor(btMultiBody* body, int link, const MotorLine& line)
    : btMultiBodyJointMotor(body, link, 0.0, 0.0), line_(line) {}

void LineLimitedJointMotor::createConstraintRows(btMultiBodyConstraintArray& constraint_rows,
                                                 btMultiBodyJacobianData& data,
                                                 const btContactSolverInfo& info) {
  const int first = constraint_rows.size();
  step_s_ = info.m_timeStep;
  // Bullet skips a motor whose impulse bound is 0; the rows' own bounds are set below.
  setMaxAppliedImpulse(line_.stall_torque_nm * step_s_);
  btMultiBodyJointMotor::createConstraintRows(constraint_rows, data, info);
  bound_speed_radps_ = m_bodyA->getJointVel(m_linkA);
  const MotorLine::Range range = line_.TorqueRangeNm(bound_speed_radps_);
  for (int row = first; row < constraint_rows.size(); ++row) {
    constraint_rows[row].m_lowerLimit = range.min_nm * step_s_;
    constraint_rows[row].m_upperLimit = range.max_nm * step_s_;
  }
}

double LineLimitedJointMotor::AppliedTorqueNm() const {
  if (step_s_ <= 0.0) return 0.0;
  // Bullet's getter only reads, but is not declared const.
  return const_cast<LineLimitedJointMotor*>(this)->getAppliedImpulse(0) / step_s_;
}

}  // namespace foresight
