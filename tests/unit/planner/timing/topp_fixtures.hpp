#pragma once
// Test support for the time-optimal parameterisation: the reference drives, analytic geometric
// paths, an independent fine-grid forward-backward reference (bisection, nothing shared with
// the planner's own reachability code), and the sampled problem and warm start its parts' tests
// share.

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/types.hpp"
#include "timing/topp_augmented_lagrangian.hpp"
#include "timing/topp_problem.hpp"
#include "timing/topp_reachability.hpp"

namespace cyber::planner::testing {

inline MotorParams krakenX60Foc() {
  MotorParams m;
  m.nominal_voltage_volts = 12.0;
  m.stall_torque_nm = 9.37;
  m.stall_current_amps = 483.0;
  m.free_current_amps = 2.0;
  m.free_speed_radps = 5800.0 * 2.0 * std::numbers::pi / 60.0;
  return m;
}

inline DriveParams elevatorDrive() {
  DriveParams d;
  d.motor = krakenX60Foc();
  d.motor_count = 2;
  d.gearing = 200.0;
  d.kS_volts = 0.15;
  d.kG_volts = 0.37;
  d.kV = 3.93;
  d.kA = 0.038;
  d.gravity = GravityModel::kConstant;
  d.voltage_limit_volts = 12.0;
  d.current_limit_amps = 80.0;
  return d;
}

inline DriveParams armDrive() {
  DriveParams d;
  d.motor = krakenX60Foc();
  d.motor_count = 1;
  d.gearing = 60.0;
  d.kS_volts = 0.15;
  d.kG_volts = 0.21;
  d.kV = 1.18;
  d.kA = 0.0056;
  d.gravity = GravityModel::kCosine;
  d.voltage_limit_volts = 12.0;
  d.current_limit_amps = 60.0;
  return d;
}

// The reference robot's chain (a carriage on a rail tilted 80 degrees carrying an arm): only the
// joint types and axes matter to the drives (the gravity angle of each joint).
inline JointChain referenceChain() {
  JointChain chain(2);
  chain[0] =
      ChainJoint{"elevator", JointType::kPrismatic, Point2(-0.4, 0.2), 80.0 * std::numbers::pi / 180.0, {0.0, 2.0}};
  chain[1] = ChainJoint{"arm", JointType::kRevolute, Point2::Zero(), 0.0, {0.0, 6.108652381980153}};
  return chain;
}

// Both drives on the reference chain.
inline DriveModel drivesOf(const DriveParams& first, const DriveParams& second) {
  return DriveModel(referenceChain(), {first, second});
}
inline DriveModel referenceDrives() { return drivesOf(elevatorDrive(), armDrive()); }

inline const JointVector kMetric{{1.0, 0.1}};  // Sigma of the reference configuration

inline double weightedNorm(const JointVector& v) { return std::sqrt(v.dot(kMetric.cwiseProduct(v))); }

// Straight line in C-space, parameterised by weighted arc length.
class LinePath final : public GeometricPath {
 public:
  LinePath(JointVector from, JointVector to) : from_(from), to_(to), length_(weightedNorm(to - from)) {}
  [[nodiscard]] double length() const override { return length_; }
  [[nodiscard]] PathPoint at(double s) const override {
    s = std::clamp(s, 0.0, length_);
    PathPoint p;
    const JointVector u = length_ > 0.0 ? JointVector((to_ - from_) / length_) : JointVector::Zero(2);
    p.q = length_ > 0.0 ? JointVector(from_ + s * u) : from_;
    p.dq_ds = u;
    p.d2q_ds2 = JointVector::Zero(from_.size());
    return p;
  }

 private:
  JointVector from_, to_;
  double length_;
};

// Circular arc in the Sigma-scaled C-space (y = Sigma^(1/2) q), unit weighted speed.
class ArcPath final : public GeometricPath {
 public:
  ArcPath(JointVector center, double radius, double angle_from, double angle_to)
      : center_(center), radius_(radius), from_(angle_from), sweep_(angle_to - angle_from) {}
  [[nodiscard]] double length() const override { return radius_ * std::abs(sweep_); }
  [[nodiscard]] PathPoint at(double s) const override {
    s = std::clamp(s, 0.0, length());
    const double dir = sweep_ >= 0.0 ? 1.0 : -1.0;
    const double phi = from_ + dir * s / radius_;
    const JointVector inv_sqrt{{1.0 / std::sqrt(kMetric[0]), 1.0 / std::sqrt(kMetric[1])}};
    PathPoint p;
    p.q = center_ + radius_ * inv_sqrt.cwiseProduct(JointVector{{std::cos(phi), std::sin(phi)}});
    p.dq_ds = dir * inv_sqrt.cwiseProduct(JointVector{{-std::sin(phi), std::cos(phi)}});
    p.d2q_ds2 = -(1.0 / radius_) * inv_sqrt.cwiseProduct(JointVector{{std::cos(phi), std::sin(phi)}});
    return p;
  }

 private:
  JointVector center_;
  double radius_, from_, sweep_;
};

// from + (to - from) u/L + wiggle * sin(pi * waves * u / L) per joint: an S-curve whose q' can
// change sign. Not unit speed (TOPP does not need it; only b_start assumes |q'(0)|_Sigma = 1).
class WigglePath final : public GeometricPath {
 public:
  WigglePath(JointVector from, JointVector to, JointVector wiggle, double waves, double length)
      : from_(from), to_(to), wiggle_(wiggle), waves_(waves), length_(length) {}
  [[nodiscard]] double length() const override { return length_; }
  [[nodiscard]] PathPoint at(double s) const override {
    s = std::clamp(s, 0.0, length_);
    const double w = std::numbers::pi * waves_ / length_;
    PathPoint p;
    p.q = from_ + (to_ - from_) * (s / length_) + wiggle_ * std::sin(w * s);
    p.dq_ds = (to_ - from_) / length_ + wiggle_ * (w * std::cos(w * s));
    p.d2q_ds2 = -wiggle_ * (w * w * std::sin(w * s));
    return p;
  }

 private:
  JointVector from_, to_, wiggle_;
  double waves_, length_;
};

// Independent reference: forward-backward pass on a fine grid with the limits at the grid nodes
// (volts/amps straight from DriveParams, bisection for every boundary).
class FineReference {
 public:
  FineReference(const GeometricPath& path, const DriveParams& elevator, const DriveParams& arm, int points)
      : drives_{elevator, arm} {
    const double length = path.length();
    for (int i = 0; i < points; ++i) {
      s_.push_back(length * i / (points - 1));
      p_.push_back(path.at(s_.back()));
    }
  }

  // Time of the fastest traversal from b_start to rest; NaN when b_start cannot be stopped.
  [[nodiscard]] double duration(double b_start) const {
    const size_t n = s_.size();
    std::vector<double> stop(n, 0.0);
    for (size_t i = n - 1; i-- > 0;) {
      const double ds = s_[i + 1] - s_[i];
      auto ok = [&](double b) {
        double lo, hi;
        return range(i, b, lo, hi) && b + 2.0 * lo * ds <= stop[i + 1] + 1e-12;
      };
      double lo = 0.0, hi = 1e4;
      if (ok(hi)) {
        stop[i] = hi;
        continue;
      }
      for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (ok(mid) ? lo : hi) = mid;
      }
      stop[i] = lo;
    }
    if (b_start > stop[0] * (1 + 1e-9) + 1e-12) return std::numeric_limits<double>::quiet_NaN();
    double b = b_start, t = 0.0;
    for (size_t i = 0; i + 1 < n; ++i) {
      const double ds = s_[i + 1] - s_[i];
      double lo = 0.0, hi = 0.0;
      range(i, b, lo, hi);
      const double next = std::clamp(b + 2.0 * hi * ds, 0.0, stop[i + 1]);
      t += 2.0 * ds / (std::sqrt(b) + std::sqrt(next));
      b = next;
    }
    return t;
  }

  [[nodiscard]] double controllableStart() const {
    double lo = 0.0, hi = 1e3;
    for (int it = 0; it < 36; ++it) {
      const double mid = 0.5 * (lo + hi);
      (std::isnan(duration(mid)) ? hi : lo) = mid;
    }
    return lo;
  }

 private:
  // The interval [lo, hi] of a admitted at node i with speed^2 b; false when empty.
  bool range(size_t i, double b, double& lo, double& hi) const {
    lo = -1e12;
    hi = 1e12;
    const PathPoint& p = p_[i];
    for (int j = 0; j < 2; ++j) {
      const DriveParams& d = drives_[j];
      const double qdot = p.dq_ds[j] * std::sqrt(b);
      // volts(a) = v0 + slope a; amps(a) = (volts(a) - emf) / R.
      const double v0 = d.volts(p.q[j], qdot, p.d2q_ds2[j] * b);
      const double slope = d.kA * p.dq_ds[j];
      const double i0 = d.amps(v0, qdot);
      const double islope = slope / d.motor.resistanceOhms();
      auto clip = [&](double value0, double value_slope, double limit) {
        if (std::abs(value_slope) < 1e-15) return std::abs(value0) <= limit;
        double a1 = (-limit - value0) / value_slope, a2 = (limit - value0) / value_slope;
        if (a1 > a2) std::swap(a1, a2);
        lo = std::max(lo, a1);
        hi = std::min(hi, a2);
        return true;
      };
      if (!clip(v0, slope, d.voltage_limit_volts) || !clip(i0, islope, d.current_limit_amps)) return false;
    }
    return lo <= hi;
  }

  DriveParams drives_[2];
  std::vector<double> s_;
  std::vector<PathPoint> p_;
};

// A sampled, normalised problem on the S-curve (q' of the arm changes sign).
inline topp::Problem wiggleProblem(int points, double b_start = 0.0) {
  const WigglePath path(JointVector{{0.2, 1.0}}, JointVector{{1.5, 4.0}}, JointVector{{0.05, 0.8}}, 3.0, 2.0);
  topp::Problem problem;
  problem.b_start = b_start;
  topp::sampleGrid(path, points, problem);
  topp::LimitMargins margins;
  margins.reset(problem.intervals());
  EXPECT_TRUE(topp::buildRows(referenceDrives(), margins, problem));
  problem.speed_bound = 1e3 / path.length();
  return problem;
}

// The S-curve's reachability profile as the augmented Lagrangian's x, with the multipliers
// estimated there: where the solver starts.
struct WarmStart {
  topp::Problem problem;
  std::vector<double> profile;  // b at the grid points
  Eigen::VectorXd x;
  topp::Multipliers multipliers;
  int active_rows = 0;  // what estimateMultipliers returned
};

inline WarmStart wiggleWarmStart(int points) {
  WarmStart w{wiggleProblem(points), {}, {}, {}, 0};
  std::vector<double> controllable;
  EXPECT_EQ(topp::forwardBackward(w.problem, w.profile, controllable).status, topp::ReachabilityStatus::kOk);
  topp::initialGuess(w.problem, w.profile, w.x);
  w.active_rows = topp::estimateMultipliers(w.problem, w.x, w.multipliers);
  return w;
}

}  // namespace cyber::planner::testing
