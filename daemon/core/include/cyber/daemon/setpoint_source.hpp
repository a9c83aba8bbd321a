#pragma once
// What the streamer needs from a trajectory: its duration and the setpoints at a time. The real
// implementation wraps the planner's Trajectory; tests use analytic fakes.

#include <memory>

#include "cyber/planner.hpp"

namespace cyber::daemon {

using planner::JointVector;

// Per joint by index (each in its joint's unit, m or rad): what one setpoint frame carries.
struct JointSetpoints {
  JointVector position;
  JointVector velocity;
  JointVector volts;  // feedforward
};

class SetpointSource {
 public:
  virtual ~SetpointSource() = default;
  [[nodiscard]] virtual double durationS() const = 0;
  // Setpoints at t seconds from the start, t clamped to [0, durationS()]. Must not allocate: the
  // streamer calls it on its real-time path.
  [[nodiscard]] virtual JointSetpoints at(double t_s) const = 0;
};

using SharedSetpointSource = std::shared_ptr<const SetpointSource>;

}  // namespace cyber::daemon
