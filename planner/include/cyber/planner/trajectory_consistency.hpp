#pragma once
// Whether a trajectory's sampled columns agree with each other the way a consumer sees them
// (docs/moving-starts.md): sampled every step_s (and at the end), the trapezoidal integral of
// the velocities must follow the positions and that of the accelerations the velocities. Exact
// derivatives can still disagree at a coarse step where the path bends sharply at speed, and then
// a 1 ms stream does not describe one motion.

#include "cyber/planner/trajectory.hpp"

namespace cyber::planner {

struct ColumnConsistency {
  double position_error = 0.0;  // largest |q - q0 - integral qdot| / the joint's travel
  double velocity_error = 0.0;  // largest |qdot - qdot0 - integral qddot| / the joint's peak speed
};

ColumnConsistency columnConsistency(const Trajectory& trajectory, double step_s);

}  // namespace cyber::planner
