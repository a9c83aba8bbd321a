#include "timing/topp_problem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace cyber::planner::topp {
namespace {

// Coefficients below this (rows are scaled to order one) are roundoff of a zero: a q' this small
// has no sign, and a row with no larger coefficient is a fixed condition.
constexpr double kTinyCoefficient = 1e-14;
// |q''| (unit-length path) beyond which the grid's density stops growing: a kink (a corner of a
// polyline, where q'' is a spike) would otherwise draw every point of the grid to itself.
constexpr double kMaxCurvatureWeight = 1e4;

int signOf(double v) { return (v > kTinyCoefficient) - (v < -kTinyCoefficient); }

std::string describe(LimitKind kind, int joint, double s) {
  static constexpr const char* kKinds[] = {"voltage", "current", "acceleration", "velocity"};
  return fmt::format("the {} limit of joint {} cannot hold at s = {:.4f} whatever the motion",
                     kKinds[static_cast<int>(kind)], joint, s);
}

// Appends lo <= alpha a + beta b + gamma c <= hi scaled by 1/scale; a row without coefficients
// is a fixed condition that holds or makes the problem infeasible.
bool addRow(Problem& problem, LinearRow row, double scale, std::string* error) {
  row.alpha /= scale;
  row.beta /= scale;
  row.gamma /= scale;
  row.lo /= scale;
  row.hi /= scale;
  if (std::abs(row.alpha) < kTinyCoefficient && std::abs(row.beta) < kTinyCoefficient &&
      std::abs(row.gamma) < kTinyCoefficient) {
    if (row.lo > 0.0 || row.hi < 0.0) {
      if (error) {
        const double s0 = problem.s[static_cast<size_t>(row.interval)];
        *error = describe(row.kind, row.joint, s0 + row.at * problem.ds(row.interval));
      }
      return false;
    }
    return true;
  }
  problem.rows.push_back(row);
  return true;
}

// The velocity margin of node n: the larger of those of the two intervals that share it.
double nodeMargin(const Problem& problem, const LimitMargins& margins, int n, int j) {
  double margin = 0.0;
  for (const int interval : {n - 1, n}) {
    if (interval >= 0 && interval < problem.intervals()) {
      margin = std::max(margin, margins.get(interval, j, LimitKind::kVelocity));
    }
  }
  return margin;
}

// Adds the profile's time to the density: cumulative[i] (density integrated up to fine point i,
// total > 0) becomes (1 - time_share) of it plus time_share of the profile's time up to u = i/fine,
// both normalised to the same total. b is linear in s between the profile's nodes, so the time of
// a fine cell is exact: 2 du / (sqrt(b_i) + sqrt(b_{i+1})). Cells at rest (b = 0 at both ends) add
// no time. Leaves cumulative unchanged when the profile takes no time.
void addTimeDensity(const ProfileView& timing, std::vector<double>& cumulative, std::vector<double>& time) {
  const std::vector<double>& s = *timing.s;
  const std::vector<double>& b = *timing.b;
  const size_t fine = cumulative.size() - 1;
  time.assign(cumulative.size(), 0.0);
  size_t node = 0;
  auto speed_at = [&](double u) {
    while (node + 2 < s.size() && s[node + 1] < u) ++node;
    const double span = s[node + 1] - s[node];
    const double f = span > 0.0 ? std::clamp((u - s[node]) / span, 0.0, 1.0) : 0.0;
    return std::sqrt(std::max(0.0, (1.0 - f) * b[node] + f * b[node + 1]));
  };
  double previous = speed_at(0.0);
  for (size_t i = 1; i <= fine; ++i) {
    const double speed = speed_at(static_cast<double>(i) / static_cast<double>(fine));
    const double sum = previous + speed;
    time[i] = sum > 0.0 ? 2.0 / (static_cast<double>(fine) * sum) : 0.0;
    previous = speed;
  }
  // No cell takes more than max_time_density times the mean time (ToppSettings says why).
  double mean_time = 0.0;
  for (size_t i = 1; i <= fine; ++i) mean_time += time[i];
  mean_time /= static_cast<double>(fine);
  if (!(mean_time > 0.0) || !std::isfinite(mean_time)) return;
  for (size_t i = 1; i <= fine; ++i) time[i] = time[i - 1] + std::min(time[i], timing.max_time_density * mean_time);
  const double total_time = time.back();
  const double total = cumulative.back();
  for (size_t i = 0; i <= fine; ++i) {
    cumulative[i] = (1.0 - timing.time_share) * cumulative[i] + timing.time_share * total * time[i] / total_time;
  }
}

}  // namespace

void sampleGrid(const GeometricPath& path, int grid_points, Problem& problem, ProfileView timing) {
  const int k_points = std::max(2, grid_points);
  const double length = path.length();
  auto sample = [&](double u) {
    PathPoint p = path.at(u >= 1.0 ? length : length * u);
    p.dq_ds *= length;
    p.d2q_ds2 *= length * length;
    return p;
  };
  // Grid density 1 + sqrt(|q''| L) (unit-length q'' here): where the path bends sharply the limits
  // change fast along s and the optimum dips, so the points gather there (a straight path keeps
  // a uniform grid). The density is sampled at 4 K points and its integral inverted.
  const int fine = 4 * (k_points - 1);
  std::vector<double>& cumulative = problem.density_workspace;
  cumulative.assign(static_cast<size_t>(fine) + 1, 0.0);
  double previous = 0.0;
  for (int i = 0; i <= fine; ++i) {
    const PathPoint p = sample(static_cast<double>(i) / fine);
    const double density = 1.0 + std::sqrt(std::min(p.d2q_ds2.norm(), kMaxCurvatureWeight));
    if (i > 0) cumulative[static_cast<size_t>(i)] = cumulative[static_cast<size_t>(i) - 1] + 0.5 * (density + previous);
    previous = density;
  }
  if (timing.s && timing.b && timing.s->size() >= 2 && timing.s->size() == timing.b->size()) {
    addTimeDensity(timing, cumulative, problem.time_workspace);
  }
  const double total = cumulative.back();
  problem.s.resize(static_cast<size_t>(k_points));
  problem.points.resize(static_cast<size_t>(k_points));
  problem.midpoints.resize(static_cast<size_t>(k_points) - 1);
  size_t cell = 0;
  for (int k = 0; k < k_points; ++k) {
    double u = 1.0;
    if (k + 1 < k_points) {
      const double target = total * k / (k_points - 1);
      while (cell + 1 < cumulative.size() && cumulative[cell + 1] < target) ++cell;
      const double span = cumulative[cell + 1] - cumulative[cell];
      const double fraction = span > 0.0 ? (target - cumulative[cell]) / span : 0.0;
      u = (static_cast<double>(cell) + std::clamp(fraction, 0.0, 1.0)) / fine;
    }
    problem.s[static_cast<size_t>(k)] = u;
    problem.points[static_cast<size_t>(k)] = sample(u);
  }
  for (int k = 0; k + 1 < k_points; ++k) {
    problem.midpoints[static_cast<size_t>(k)] =
        sample(0.5 * (problem.s[static_cast<size_t>(k)] + problem.s[static_cast<size_t>(k) + 1]));
  }
}

void scaleTime(const Problem& in, double time_scale_s, Problem& out) {
  const double t2 = time_scale_s * time_scale_s;
  out.s = in.s;
  out.points.clear();
  out.midpoints.clear();
  out.rows = in.rows;
  out.row_begin = in.row_begin;
  for (LinearRow& row : out.rows) {
    // alpha a + beta b + gamma c with a = a'/T^2, b = b'/T^2, c = c'/T.
    row.alpha /= t2;
    row.beta /= t2;
    row.gamma /= time_scale_s;
  }
  out.b_start = in.b_start * t2;
  out.b_end = in.b_end * t2;
  out.cost_scale = in.cost_scale;  // sum 2 ds d is now the duration in units of the time scale
  out.speed_bound = in.speed_bound * time_scale_s;
}

namespace {

// Signs of qdot_j on the interval (Coulomb friction flips where q'_j changes sign, and the rows
// must hold on either side of the flip; both signs where q'_j vanishes; 0 too where the profile is
// pinned at rest), as {lowest, highest}.
std::array<int, 2> coulombSigns(const std::array<const PathPoint*, 3>& samples, int j, bool pinned_at_rest) {
  int sign_lo = 1;
  int sign_hi = -1;
  for (const PathPoint* q : samples) {
    sign_lo = std::min(sign_lo, signOf(q->dq_ds[j]));
    sign_hi = std::max(sign_hi, signOf(q->dq_ds[j]));
  }
  if (sign_lo == 0 && sign_hi == 0) {
    sign_lo = -1;
    sign_hi = 1;
  }
  if (pinned_at_rest) {
    sign_lo = std::min(sign_lo, 0);
    sign_hi = std::max(sign_hi, 0);
  }
  return {sign_lo, sign_hi};
}

// One place of an interval: its index k, its fraction `at` (0, 1 or 1/2), which of the three it
// is, and its path sample.
struct RowPlace {
  int k;
  double at;
  int place;
  const PathPoint& p;
};

// The rows of joint j at one place: voltage, current, acceleration and (at nodes) velocity. Apart
// from buildRows so that the loops over intervals and places read on their own.
bool addJointRows(const DriveParams& d, const PathVoltage& pv, const LimitMargins& margins, const RowPlace& where,
                  int j, std::array<int, 2> signs, Problem& problem, std::string* error) {
  const int k = where.k;
  const double at = where.at;
  const int place = where.place;
  const int intervals = problem.intervals();
  const double inf = std::numeric_limits<double>::infinity();
  const double qp = where.p.dq_ds[j];
  const double qpp = where.p.d2q_ds2[j];
  const double coulomb_lo = d.kS_volts * signs[0];
  const double coulomb_hi = d.kS_volts * signs[1];
  const double gravity = pv.offset;
  const auto joint = static_cast<std::int8_t>(j);

  // Voltage: V = kS sgn + gravity + alpha a + beta b + gamma c (DriveModel::pathVoltage), |V| <= Vmax.
  const double v_limit = d.voltage_limit_volts - margins.get(k, j, LimitKind::kVoltage);
  LinearRow voltage{k,
                    at,
                    pv.alpha,
                    pv.beta,
                    pv.gamma,
                    -v_limit - gravity - coulomb_lo,
                    v_limit - gravity - coulomb_hi,
                    joint,
                    LimitKind::kVoltage};
  if (!addRow(problem, voltage, d.voltage_limit_volts, error)) return false;

  // Current: I R = V - G q' c / Kv, |I| <= Imax.
  const double r = d.motor.resistanceOhms();
  const double back_emf = d.gearing / d.motor.kvRadpsPerVolt();
  const double i_limit = d.current_limit_amps - margins.get(k, j, LimitKind::kCurrent);
  LinearRow current{k,
                    at,
                    pv.alpha,
                    pv.beta,
                    pv.gamma - back_emf * qp,
                    -r * i_limit - gravity - coulomb_lo,
                    r * i_limit - gravity - coulomb_hi,
                    joint,
                    LimitKind::kCurrent};
  if (!addRow(problem, current, r * d.current_limit_amps, error)) return false;

  if (d.acceleration_limit) {
    const double a_limit = *d.acceleration_limit - margins.get(k, j, LimitKind::kAcceleration);
    LinearRow accel{k, at, qp, qpp, 0.0, -a_limit, a_limit, joint, LimitKind::kAcceleration};
    if (!addRow(problem, accel, *d.acceleration_limit, error)) return false;
  }
  // The velocity limit involves b only: one row per node; between nodes the continuous
  // check holds it, as it does every limit. Rows at the midpoints as well would make three
  // rows bound two b's along a stretch at the limit: the multipliers are then not unique and
  // the solver needs 20-50 times more iterations (docs/algorithm.md section 3).
  if (d.velocity_limit && place != 2 && (place == 0 || k + 1 == intervals)) {
    const double v_max = std::max(0.0, *d.velocity_limit - nodeMargin(problem, margins, k + place, j));
    LinearRow velocity{k, at, 0.0, qp * qp, 0.0, -inf, v_max * v_max, joint, LimitKind::kVelocity};
    if (!addRow(problem, velocity, *d.velocity_limit * *d.velocity_limit, error)) return false;
  }
  return true;
}

}  // namespace

Result<Done> buildRows(const DriveModel& drives, const LimitMargins& margins, Problem& problem) {
  const int intervals = problem.intervals();
  std::string error;
  problem.rows.clear();
  problem.row_begin.assign(static_cast<size_t>(intervals) + 1, 0);
  for (int k = 0; k < intervals; ++k) {
    problem.row_begin[static_cast<size_t>(k)] = static_cast<int>(problem.rows.size());
    const std::array<const PathPoint*, 3> samples = {&problem.points[static_cast<size_t>(k)],
                                                     &problem.points[static_cast<size_t>(k) + 1],
                                                     &problem.midpoints[static_cast<size_t>(k)]};
    constexpr double kAt[3] = {0.0, 1.0, 0.5};
    for (int place = 0; place < 3; ++place) {
      const PathPoint& p = *samples[static_cast<size_t>(place)];
      const bool pinned_at_rest = (place == 0 && k == 0 && problem.b_start == 0.0) ||
                                  (place == 1 && k + 1 == intervals && problem.b_end == 0.0);
      const PerJoint<PathVoltage> voltages = drives.pathVoltages(p);
      for (int j = 0; j < voltages.size(); ++j) {
        if (!addJointRows(drives.drive(j), voltages[j], margins, RowPlace{k, kAt[place], place, p}, j,
                          coulombSigns(samples, j, pinned_at_rest), problem, &error)) {
          return PlanError{PlanStatus::kInvalidInput, std::move(error)};
        }
      }
    }
  }
  problem.row_begin[static_cast<size_t>(intervals)] = static_cast<int>(problem.rows.size());
  return Done{};
}

}  // namespace cyber::planner::topp
