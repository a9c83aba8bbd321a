#include "path/path_optimizer.hpp"

#include "math/roundoff.hpp"
#include "math/weighted_norm.hpp"

#include <algorithm>
#include <cmath>

namespace cyber::planner {
namespace {

constexpr int kMaxClosePairs = 64;

}  // namespace

SmoothingObjective::SmoothingObjective(const CollisionWorld& world, std::vector<JointVector> prior, int fixed_head,
                                       const RobotModel& model, const SmoothingSettings& settings)
    : world_(world),
      prior_(std::move(prior)),
      fixed_head_(std::max(1, fixed_head)),
      free_count_(std::max(0, static_cast<int>(prior_.size()) - 1 - fixed_head_)),
      metric_(model.planner.metric),
      settings_(settings),
      limits_(model.jointCount()),
      limit_margin_(model.planner.grid.joint_limit_margin),
      points_(prior_) {
  for (int j = 0; j < model.jointCount(); ++j) limits_[j] = model.range(j);
}

Eigen::VectorXd SmoothingObjective::priorVariables() const {
  Eigen::VectorXd x(jointCount() * free_count_);
  for (int k = 0; k < free_count_; ++k) {
    for (int j = 0; j < jointCount(); ++j) x[j * free_count_ + k] = prior_[static_cast<size_t>(fixed_head_ + k)][j];
  }
  return x;
}

std::vector<JointVector> SmoothingObjective::waypoints(const Eigen::VectorXd& x) const {
  std::vector<JointVector> out = prior_;
  for (int k = 0; k < free_count_; ++k) out[static_cast<size_t>(fixed_head_ + k)] = variablesOf(x, k);
  return out;
}

double SmoothingObjective::evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const {
  const int m = free_count_;
  const int n = static_cast<int>(prior_.size());
  const int joints = jointCount();
  for (int k = 0; k < m; ++k) points_[static_cast<size_t>(fixed_head_ + k)] = variablesOf(x, k);
  gradient.setZero();
  // Gradient of a term in waypoint i, joint j, lands in variable (i - fixed_head) + j * m when
  // waypoint i is free.
  auto add = [&](int i, const JointVector& g) {
    const int k = i - fixed_head_;
    if (k < 0 || k >= m) return;
    for (int j = 0; j < joints; ++j) gradient[j * m + k] += g[j];
  };
  const JointVector sigma = metric_;
  double cost = 0.0;

  // Obstacles and joint limits, free waypoints only.
  const double d0 = settings_.obstacle_decay_m;
  const double cutoff = kObstacleCutoffDecays * d0;
  const double e_cut = std::exp(-2.0 * cutoff / d0);
  for (int k = 0; k < m; ++k) {
    const int i = fixed_head_ + k;
    const JointVector& q = points_[static_cast<size_t>(i)];
    if (settings_.obstacle_weight > 0.0 && d0 > 0.0) {
      SignedDistance pairs[kMaxClosePairs];
      const int count = world_.closePairs(q, cutoff, pairs);
      for (int p = 0; p < count; ++p) {
        const SignedDistance& d = pairs[p];
        const double e = std::exp(-2.0 * d.value / d0);
        cost += settings_.obstacle_weight * (e - e_cut * (1.0 + 2.0 * (cutoff - d.value) / d0));
        add(i, settings_.obstacle_weight * (-2.0 / d0) * (e - e_cut) * d.gradient);
      }
    }
    for (int j = 0; j < joints; ++j) {
      const double below = limits_[j].min + limit_margin_ - q[j];
      const double above = q[j] - (limits_[j].max - limit_margin_);
      const double excess = below > 0.0 ? -below : (above > 0.0 ? above : 0.0);
      if (excess != 0.0) {
        cost += settings_.joint_limit_weight * excess * excess;
        JointVector g = JointVector::Zero(joints);
        g[j] = 2.0 * settings_.joint_limit_weight * excess;
        add(i, g);
      }
    }
    const JointVector deviation = q - prior_[static_cast<size_t>(i)];
    cost += settings_.prior_weight * deviation.dot(sigma.cwiseProduct(deviation));
    add(i, 2.0 * settings_.prior_weight * sigma.cwiseProduct(deviation));
  }
  // Length: every consecutive pair.
  for (int i = 0; i + 1 < n; ++i) {
    const JointVector e = points_[static_cast<size_t>(i) + 1] - points_[static_cast<size_t>(i)];
    cost += settings_.length_weight * e.dot(sigma.cwiseProduct(e));
    const JointVector g = 2.0 * settings_.length_weight * sigma.cwiseProduct(e);
    add(i + 1, g);
    add(i, -g);
  }
  // Smoothness: every interior waypoint.
  for (int i = 1; i + 1 < n; ++i) {
    const JointVector c = points_[static_cast<size_t>(i) - 1] - 2.0 * points_[static_cast<size_t>(i)] +
                          points_[static_cast<size_t>(i) + 1];
    cost += settings_.smoothness_weight * c.dot(sigma.cwiseProduct(c));
    const JointVector g = 2.0 * settings_.smoothness_weight * sigma.cwiseProduct(c);
    add(i - 1, g);
    add(i, -2.0 * g);
    add(i + 1, g);
  }
  return cost;
}

void SmoothingObjective::quadraticHessian(int joint, BandedCholesky& hessian) const {
  const int m = free_count_;
  const int n = static_cast<int>(prior_.size());
  const double sigma = metric_[joint];
  hessian.reset(m, 2);
  // Adds 2 w r r^T for a row r with coefficients c at waypoints first, first+1, ...
  auto add_row = [&](double w, int first, std::initializer_list<double> coefficients) {
    int a = first;
    for (double ca : coefficients) {
      int b = first;
      for (double cb : coefficients) {
        const int ka = a - fixed_head_, kb = b - fixed_head_;
        if (ka >= 0 && ka < m && kb >= ka && kb < m) hessian.add(kb, ka, 2.0 * w * sigma * ca * cb);
        ++b;
      }
      ++a;
    }
  };
  for (int i = fixed_head_; i + 1 < n; ++i) add_row(settings_.prior_weight, i, {1.0});
  for (int i = 0; i + 1 < n; ++i) add_row(settings_.length_weight, i, {-1.0, 1.0});
  for (int i = 1; i + 1 < n; ++i) add_row(settings_.smoothness_weight, i - 1, {1.0, -2.0, 1.0});
}

SmoothingResult optimizePath(const CollisionWorld& world, const std::vector<JointVector>& prior, int fixed_head,
                             const RobotModel& model, const SmoothingSettings& settings) {
  SmoothingResult result;
  const SmoothingObjective objective(world, prior, fixed_head, model, settings);
  const int m = objective.freeCount();
  if (m == 0) {
    result.waypoints = prior;
    return result;
  }
  const int joints = model.jointCount();
  BandedCholesky factors[kMaxJoints];
  bool preconditioned = true;
  for (int j = 0; j < joints; ++j) {
    objective.quadraticHessian(j, factors[j]);
    // A pivot floor of 0 replaces only pivots that are not positive: then there is no factor.
    preconditioned = preconditioned && factors[j].factor(0.0) == 0;
  }
  const Eigen::VectorXd x_prior = objective.priorVariables();
  Eigen::VectorXd x(joints * m), gradient_x(joints * m);
  // x = x_prior + L^-T y, per joint block; without a factor (all quadratic weights zero) y = x - x_prior.
  auto to_x = [&](const Eigen::VectorXd& y) {
    for (int j = 0; j < joints; ++j) {
      x.segment(j * m, m) = y.segment(j * m, m);
      if (preconditioned) factors[j].solveUpper(x.segment(j * m, m));
    }
    x += x_prior;
  };
  const LbfgsObjective f = [&](const Eigen::VectorXd& y, Eigen::VectorXd& gradient_y) {
    to_x(y);
    const double cost = objective.evaluate(x, gradient_x);
    for (int j = 0; j < joints; ++j) {
      gradient_y.segment(j * m, m) = gradient_x.segment(j * m, m);
      if (preconditioned) factors[j].solveLower(gradient_y.segment(j * m, m));
    }
    return cost;
  };
  LbfgsSettings lbfgs;
  lbfgs.max_iterations = settings.max_iterations;
  lbfgs.gradient_tolerance = settings.gradient_tolerance;
  lbfgs.relative_cost_tolerance = settings.relative_cost_tolerance;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(joints * m);
  result.lbfgs = minimizeLbfgs(f, y, lbfgs);
  to_x(y);
  // The limit term is soft (a stiff one slows L-BFGS down a lot); clamp what it leaves.
  const double limit_margin = model.planner.grid.joint_limit_margin;
  auto inside = [limit_margin](double v, const JointRange& range) {
    const double margin = std::min(limit_margin, 0.5 * (range.max - range.min));
    return std::clamp(v, range.min + margin, range.max - margin);
  };
  for (int j = 0; j < joints; ++j) {
    for (int k = 0; k < m; ++k) x[j * m + k] = inside(x[j * m + k], model.range(j));
  }
  result.waypoints = objective.waypoints(x);
  return result;
}

std::vector<JointVector> resamplePolyline(const std::vector<JointVector>& polyline, const JointVector& metric,
                                          double max_spacing) {
  if (polyline.size() < 2) return polyline;
  std::vector<double> cumulative(polyline.size(), 0.0);
  for (size_t k = 1; k < polyline.size(); ++k) {
    cumulative[k] = cumulative[k - 1] + weightedNorm(polyline[k] - polyline[k - 1], metric);
  }
  const double total = cumulative.back();
  if (!(total > 0.0) || !(max_spacing > 0.0)) return {polyline.front(), polyline.back()};
  const int segments = std::max(1, static_cast<int>(std::ceil(total / max_spacing - kWholeCountSlack)));
  std::vector<JointVector> out;
  out.reserve(static_cast<size_t>(segments) + 1);
  out.push_back(polyline.front());
  size_t k = 1;
  for (int i = 1; i < segments; ++i) {
    const double s = total * i / segments;
    while (k + 1 < polyline.size() && cumulative[k] < s) ++k;
    const double span = cumulative[k] - cumulative[k - 1];
    const double f = span > 0.0 ? (s - cumulative[k - 1]) / span : 0.0;
    out.push_back(polyline[k - 1] + f * (polyline[k] - polyline[k - 1]));
  }
  out.push_back(polyline.back());
  return out;
}

}  // namespace cyber::planner
