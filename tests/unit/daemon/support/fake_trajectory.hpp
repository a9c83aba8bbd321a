#pragma once
// An analytic trajectory for daemon tests: per joint a cubic Hermite from (start, start velocity)
// to (goal, 0) over a fixed duration, with the WPILib feedforward of the drives as volts. Smooth
// and exact, so continuity tests have something to compare against.

#include <algorithm>
#include <limits>
#include <memory>

#include "cyber/daemon/setpoint_source.hpp"
#include "cyber/planner.hpp"

namespace cyber::daemon::test {

class HermiteTrajectory final : public SetpointSource {
 public:
  HermiteTrajectory(JointVector start, JointVector start_velocity, JointVector goal, double duration_s,
                    const planner::DriveModel& drives)
      : p0_(std::move(start)),
        v0_(std::move(start_velocity)),
        p1_(std::move(goal)),
        duration_s_(duration_s),
        drives_(drives) {}

  [[nodiscard]] double durationS() const override { return duration_s_; }

  [[nodiscard]] JointSetpoints at(double t_s) const override {
    JointSetpoints out;
    if (duration_s_ <= 0.0) {
      out.position = p1_;
      out.velocity = JointVector::Zero(p1_.size());
      out.volts = drives_.volts(p1_, JointVector::Zero(p1_.size()), JointVector::Zero(p1_.size()));
      return out;
    }
    const double T = duration_s_;
    const double u = std::clamp(t_s, 0.0, T) / T;
    // Hermite basis with end velocity 0: q = h00 p0 + h10 T v0 + h01 p1.
    const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u, h01 = -2 * u * u * u + 3 * u * u;
    const double d00 = (6 * u * u - 6 * u) / T, d10 = (3 * u * u - 4 * u + 1), d01 = (-6 * u * u + 6 * u) / T;
    const double a00 = (12 * u - 6) / (T * T), a10 = (6 * u - 4) / T, a01 = (-12 * u + 6) / (T * T);
    out.position = h00 * p0_ + h10 * T * v0_ + h01 * p1_;
    out.velocity = d00 * p0_ + d10 * v0_ + d01 * p1_;
    const JointVector acceleration = a00 * p0_ + a10 * v0_ + a01 * p1_;
    out.volts = drives_.volts(out.position, out.velocity, acceleration);
    return out;
  }

 private:
  JointVector p0_, v0_, p1_;
  double duration_s_;
  planner::DriveModel drives_;
};

// A trajectory that holds `position` and turns its elevator setpoint to NaN after nan_after_s: a
// setpoint no frame can carry.
class NanAfterTrajectory final : public SetpointSource {
 public:
  NanAfterTrajectory(double nan_after_s, JointVector position) : nan_after_s_(nan_after_s), position_(position) {}
  [[nodiscard]] double durationS() const override { return 1.0; }
  [[nodiscard]] JointSetpoints at(double t_s) const override {
    JointSetpoints s;
    s.position = position_;
    s.velocity = JointVector::Zero(position_.size());
    s.volts = JointVector::Zero(position_.size());
    if (t_s > nan_after_s_) s.position[0] = std::numeric_limits<double>::quiet_NaN();
    return s;
  }

 private:
  double nan_after_s_;
  JointVector position_;
};

inline SharedSetpointSource makeHermite(const JointVector& start, const JointVector& start_velocity,
                                        const JointVector& goal, double duration_s, const planner::RobotModel& robot) {
  return std::make_shared<HermiteTrajectory>(start, start_velocity, goal, duration_s, robot.driveModel({}));
}

}  // namespace cyber::daemon::test
