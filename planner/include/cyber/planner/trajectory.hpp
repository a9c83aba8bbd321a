#pragma once
// A time-parameterised path: the geometric path q(s) and the time map t(s) of algorithm.md
// section 3. Between grid points the path acceleration a = s'' is constant (b = s'^2 linear in s),
// so positions, velocities and accelerations follow exactly from the grid values (b_k, a_k).

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "cyber/planner/geometric_path.hpp"
#include "cyber/planner/result.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

struct TrajectorySample {
  double t = 0.0;      // s
  double s = 0.0;      // path parameter
  double sdot = 0.0;   // ds/dt
  double sddot = 0.0;  // d2s/dt2 (constant on each grid interval)
  JointVector q = JointVector::Zero();
  JointVector qdot = JointVector::Zero();
  JointVector qddot = JointVector::Zero();
  JointVector volts = JointVector::Zero();  // feedforward voltage of each joint (DriveModel::volts)
  JointVector amps = JointVector::Zero();   // current of each motor of each joint (DriveModel::amps)
};

class Trajectory {
 public:
  // Validates the profile: grid strictly increasing from 0 to path->length(), b >= 0 finite, no
  // interval with b = 0 at both ends (it would take forever) unless the path has zero length.
  static Result<Trajectory> create(std::shared_ptr<const GeometricPath> path, const DriveModel& drives,
                                   std::vector<double> s_grid, std::vector<double> b_grid);

  [[nodiscard]] double duration_s() const { return t_grid_.empty() ? 0.0 : t_grid_.back(); }
  // The state at time t (clamped to [0, duration]). Does not allocate.
  [[nodiscard]] TrajectorySample sample(double t) const;
  // The same without volts and amps (left zero): for checks that need the motion alone.
  [[nodiscard]] TrajectorySample sampleMotion(double t) const;
  // t(s) and its inverse s(t); both clamp their argument.
  [[nodiscard]] double timeAt(double s) const;
  [[nodiscard]] double pathParameterAt(double t) const;

  [[nodiscard]] const GeometricPath& path() const { return *path_; }
  [[nodiscard]] const std::shared_ptr<const GeometricPath>& sharedPath() const { return path_; }
  [[nodiscard]] const DriveParams& drive(int joint) const { return drives_.drive(joint); }
  [[nodiscard]] const DriveModel& drives() const { return drives_; }
  [[nodiscard]] const std::vector<double>& sGrid() const { return s_grid_; }
  [[nodiscard]] const std::vector<double>& bGrid() const { return b_grid_; }
  [[nodiscard]] const std::vector<double>& tGrid() const { return t_grid_; }

 private:
  Trajectory() = default;
  // Interval index k with grid time t_k <= t (the last interval for t at the end).
  [[nodiscard]] size_t intervalAtTime(double t) const;
  [[nodiscard]] size_t intervalAtS(double s) const;

  std::shared_ptr<const GeometricPath> path_;
  DriveModel drives_;
  std::vector<double> s_grid_;
  std::vector<double> b_grid_;
  std::vector<double> a_grid_;  // per interval: (b_{k+1} - b_k) / (2 ds_k)
  std::vector<double> t_grid_;
};

// The drive limits a trajectory is held to (DriveParams): voltage and current always, velocity and
// acceleration where the drive sets them.
enum class DriveLimit { kVoltage, kCurrent, kVelocity, kAcceleration };

// Calls visit(t_s, joint, limit, value, bound) for every drive limit of every joint at every
// sample `step_s` apart and at the last instant: the one definition of what the 1 ms limit check
// samples (algorithm.md section 3), for the optimiser's check and for profiles made outside it.
template <class Visit>
void forEachLimitSample(const Trajectory& trajectory, double step_s, Visit&& visit) {
  const double duration = trajectory.duration_s();
  const long samples = static_cast<long>(std::floor(duration / step_s)) + 1;
  for (long i = 0; i <= samples; ++i) {
    const double t = i == samples ? duration : std::min(duration, static_cast<double>(i) * step_s);
    const TrajectorySample s = trajectory.sample(t);
    for (int j = 0; j < kJointCount; ++j) {
      const DriveParams& d = trajectory.drive(j);
      visit(t, j, DriveLimit::kVoltage, s.volts[j], d.voltage_limit_volts);
      visit(t, j, DriveLimit::kCurrent, s.amps[j], d.current_limit_amps);
      if (d.velocity_limit) visit(t, j, DriveLimit::kVelocity, s.qdot[j], *d.velocity_limit);
      if (d.acceleration_limit) visit(t, j, DriveLimit::kAcceleration, s.qddot[j], *d.acceleration_limit);
    }
  }
}

// Whether every sample `step_s` apart (and the last) keeps each joint's voltage, current and
// optional velocity and acceleration within its limit times (1 + tolerance).
[[nodiscard]] bool withinDriveLimits(const Trajectory& trajectory, double step_s, double tolerance);

// The same check for a profile made outside the optimiser (a stop's reachability profile, a
// slowed trajectory) at the optimiser's step, accepting half its tolerance: less than the
// optimiser accepts at its own samples, so that other sampling instants stay within it.
[[nodiscard]] bool withinDriveLimits(const Trajectory& trajectory, const ToppSettings& settings);

// The same path `factor` (>= 1) times slower: b / factor^2, so velocities shrink by 1 / factor and
// path accelerations by 1 / factor^2 (a start at rest stays at rest). Drive limits are not
// checked here: withinDriveLimits.
[[nodiscard]] Result<Trajectory> slowedDown(const Trajectory& trajectory, double factor);

// The same path from rest with a gentler start: b is capped by the line b = 2 scale a_0 s (a_0 the
// first interval's path acceleration, 0 < scale <= 1) until the line meets the profile, which is
// unchanged from there on. The path starts with scale times its first acceleration and joins the
// original profile later, at the same speed: it moves the time of the early acceleration switches
// that a uniform slowdown hardly moves (docs/moving-starts.md, "Consistent columns"). Drive limits
// are not checked here: withinDriveLimits.
[[nodiscard]] Result<Trajectory> gentlerStart(const Trajectory& trajectory, double scale);

}  // namespace cyber::planner
