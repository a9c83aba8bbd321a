#include "cyber/daemon/hold_model.hpp"

namespace cyber::daemon {

JointSetpoints HoldModel::hold(const JointVector& q) const {
  JointSetpoints out;
  out.position = q;
  out.velocity.setZero();
  // volts(q, 0, 0) = kG * g(q): kS * sgn(0) vanishes at rest.
  out.volts = JointVector(elevator_.volts(q[planner::kElevator], 0.0, 0.0), arm_.volts(q[planner::kArm], 0.0, 0.0));
  return out;
}

}  // namespace cyber::daemon
