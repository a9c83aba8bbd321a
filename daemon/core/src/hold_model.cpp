#include "cyber/daemon/hold_model.hpp"

namespace cyber::daemon {

JointSetpoints HoldModel::hold(const JointVector& q) const {
  JointSetpoints out;
  out.position = q;
  out.velocity = JointVector::Zero(q.size());
  // At rest only gravity is left: kS * sgn(0) vanishes.
  out.volts = drives_.volts(q, JointVector::Zero(q.size()), JointVector::Zero(q.size()));
  return out;
}

}  // namespace cyber::daemon
