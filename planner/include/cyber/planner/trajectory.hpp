#pragma once
// A time-parameterised path: the geometric path q(s) and the time map t(s) of algorithm.md
// section 3. Between grid points the path acceleration a = s'' is constant (b = s'^2 linear in s),
// so positions, velocities and accelerations follow exactly from the grid values (b_k, a_k).

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

/// What the time-optimal parameterisation (TOPP) did; filled on success and on failure.
struct ToppReport {
  int grid_points = 0;
  int outer_iterations = 0;      ///< summed over all solves (first solve and limit refinements)
  int inner_iterations = 0;      ///< L-BFGS iterations, summed
  int evaluations = 0;           ///< evaluations of L_rho, summed
  int refinements = 0;           ///< re-solves after the continuous limit check tightened limits
  double primal_residual = 0.0;  ///< of the last solve
  double dual_residual = 0.0;
  double penalty = 0.0;
  double warm_start_duration_s = 0.0;  ///< of the forward-backward profile the solver started from
  double controllable_start_b = 0.0;   ///< largest b_start the path could have stopped from
  /// Start speed planned / start speed asked: 1, or just below when a start past the controllable
  /// set by at most ToppSettings::limit_check_tolerance (a splice from the solver's own trajectory
  /// at a limit) was planned from the fastest start that can be stopped.
  double start_speed_ratio = 1.0;
  /// Largest |value| / limit over the samples of the continuous check (1 = at the limit).
  double peak_voltage_ratio = 0.0;
  double peak_current_ratio = 0.0;
  double peak_velocity_ratio = 0.0;      ///< 0 when no joint has a velocity limit
  double peak_acceleration_ratio = 0.0;  ///< 0 when no joint has an acceleration limit
};

/// The state of a trajectory at one time: positions, velocities, accelerations, volts, amps.
struct TrajectorySample {
  double t = 0.0;      ///< s
  double s = 0.0;      ///< path parameter
  double sdot = 0.0;   ///< ds/dt
  double sddot = 0.0;  ///< d2s/dt2 (constant on each grid interval)
  JointVector q;
  JointVector qdot;
  JointVector qddot;
  JointVector volts;  ///< feedforward voltage of each joint (DriveModel::volts)
  JointVector amps;   ///< current of each motor of each joint (DriveModel::amps)
};

/// A time-parameterised path: what a Plan carries and the daemon streams.
class Trajectory {
 public:
  /// Validates the profile: grid strictly increasing from 0 to path->length(), b >= 0 finite, no
  /// interval with b = 0 at both ends (it would take forever) unless the path has zero length.
  static Result<Trajectory> create(std::shared_ptr<const GeometricPath> path, const DriveModel& drives,
                                   std::vector<double> s_grid, std::vector<double> b_grid);

  [[nodiscard]] double duration_s() const { return t_grid_.empty() ? 0.0 : t_grid_.back(); }
  /// The state at time t (clamped to [0, duration]). Does not allocate.
  [[nodiscard]] TrajectorySample sample(double t) const;
  /// The same without volts and amps (left zero): for checks that need the motion alone.
  [[nodiscard]] TrajectorySample sampleMotion(double t) const;
  /// t(s) and its inverse s(t); both clamp their argument.
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
  /// Interval index k with grid time t_k <= t (the last interval for t at the end).
  [[nodiscard]] size_t intervalAtTime(double t) const;
  [[nodiscard]] size_t intervalAtS(double s) const;

  std::shared_ptr<const GeometricPath> path_;
  DriveModel drives_;
  std::vector<double> s_grid_;
  std::vector<double> b_grid_;
  std::vector<double> a_grid_;  ///< per interval: (b_{k+1} - b_k) / (2 ds_k)
  std::vector<double> t_grid_;
};

/// The drive limits a trajectory is held to (DriveParams): voltage and current always, velocity and
/// acceleration where the drive sets them.
enum class DriveLimit { kVoltage, kCurrent, kVelocity, kAcceleration };

/// Calls visit(t_s, joint, limit, value, bound) for every drive limit of every joint at every
/// sample `step_s` apart and at the last instant: the one definition of what the 1 ms limit check
/// samples (algorithm.md section 3), for the optimiser's check and for profiles made outside it.
template <class Visit>
void forEachLimitSample(const Trajectory& trajectory, double step_s, Visit&& visit) {
  const double duration = trajectory.duration_s();
  const long samples = static_cast<long>(std::floor(duration / step_s)) + 1;
  for (long i = 0; i <= samples; ++i) {
    const double t = i == samples ? duration : std::min(duration, static_cast<double>(i) * step_s);
    const TrajectorySample s = trajectory.sample(t);
    for (int j = 0; j < s.q.size(); ++j) {
      const DriveParams& d = trajectory.drive(j);
      visit(t, j, DriveLimit::kVoltage, s.volts[j], d.voltage_limit_volts);
      visit(t, j, DriveLimit::kCurrent, s.amps[j], d.current_limit_amps);
      if (d.velocity_limit) visit(t, j, DriveLimit::kVelocity, s.qdot[j], *d.velocity_limit);
      if (d.acceleration_limit) visit(t, j, DriveLimit::kAcceleration, s.qddot[j], *d.acceleration_limit);
    }
  }
}

/// Whether every sample `step_s` apart (and the last) keeps each joint's voltage, current and
/// optional velocity and acceleration within its limit times (1 + tolerance).
[[nodiscard]] bool withinDriveLimits(const Trajectory& trajectory, double step_s, double tolerance);

/// The same check for a profile made outside the optimiser (a stop's reachability profile, a
/// slowed trajectory) at the optimiser's step, accepting half its tolerance: less than the
/// optimiser accepts at its own samples, so that other sampling instants stay within it.
[[nodiscard]] bool withinDriveLimits(const Trajectory& trajectory, const ToppSettings& settings);

/// The same path `factor` (>= 1) times slower: b / factor^2, so velocities shrink by 1 / factor and
/// path accelerations by 1 / factor^2 (a start at rest stays at rest). Drive limits are not
/// checked here: withinDriveLimits.
[[nodiscard]] Result<Trajectory> slowedDown(const Trajectory& trajectory, double factor);

/// The same path from rest with a gentler start: b is capped by the line b = 2 scale a_0 s (a_0 the
/// first interval's path acceleration, 0 < scale <= 1) until the line meets the profile, which is
/// unchanged from there on. The path starts with scale times its first acceleration and joins the
/// original profile later, at the same speed: it moves the time of the early acceleration switches
/// that a uniform slowdown hardly moves (docs/moving-starts.md, "Consistent columns"). Drive limits
/// are not checked here: withinDriveLimits.
[[nodiscard]] Result<Trajectory> gentlerStart(const Trajectory& trajectory, double scale);

/// The fastest ride along a trajectory's path as a check that reads only its samples sees it (an
/// external referee's along-path ratio, docs/moving-starts.md, "The CSV's spacing"): independent of
/// the planner's TOPP, sharing only the drive model's voltages and currents. Where the path's
/// tangent in its own time goes to zero (a turn, the end at rest) samples far apart let the ride
/// pass faster than any motor could; the gain shrinks with the spacing.

/// The shortest time in which the path q(s) of `trajectory`, s its own time, read at the increasing
/// times `times_s` (the first 0, the last its duration), can be traversed within its drives'
/// limits: each sample's voltage, current and optional velocity and acceleration limits bound the
/// path acceleration s'' to an interval at each path speed squared b = s'^2; a backward pass finds
/// the largest b from which the end is still reachable, a greedy forward pass rides at the upper
/// bound (reachability analysis, docs/algorithm.md section 3). A moving start keeps its speed
/// (b = 1 at s = 0); the ride ends at rest. nullopt when these samples admit no ride.
[[nodiscard]] std::optional<double> fastestRideAlongSamples(const Trajectory& trajectory,
                                                            std::span<const double> times_s);

/// The same on samples evenly about `step_s` apart, the last at the end.
[[nodiscard]] std::optional<double> fastestRideAlongPath(const Trajectory& trajectory, double step_s);

/// Whether a trajectory's sampled columns agree with each other the way a consumer sees them
/// (docs/moving-starts.md): sampled every step_s (and at the end), the trapezoidal integral of
/// the velocities must follow the positions and that of the accelerations the velocities. Exact
/// derivatives can still disagree at a coarse step where the path bends sharply at speed, and then
/// a 1 ms stream does not describe one motion.

/// How far a trajectory's sampled columns are from integrating to each other.
struct ColumnConsistency {
  double position_error = 0.0;  ///< largest |q - q0 - integral qdot| / the joint's travel
  double velocity_error = 0.0;  ///< largest |qdot - qdot0 - integral qddot| / the joint's peak speed
};

/// The columns' largest disagreement when the trajectory is sampled every step_s.
ColumnConsistency columnConsistency(const Trajectory& trajectory, double step_s);

/// Whether the trapezoidal integrals of the trajectory's columns follow its positions and
/// velocities within MotionSettings' tolerances at the CSV's step (consistency_step_s), or at
/// samples `step_s` apart.
bool columnsAgree(const MotionSettings& settings, const Trajectory& trajectory);
/// The same at samples `step_s` apart.
bool columnsAgree(const MotionSettings& settings, const Trajectory& trajectory, double step_s);

}  // namespace cyber::planner
