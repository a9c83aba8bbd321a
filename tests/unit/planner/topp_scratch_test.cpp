#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>

#include <gtest/gtest.h>

#include "cyber/planner/topp.hpp"
#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {
using namespace testing;

void run(const char* name, std::shared_ptr<const GeometricPath> path, double b_start, ToppSettings settings = {}) {
  if (getenv("RHO0")) settings.penalty_initial = atof(getenv("RHO0"));
  if (getenv("GROW")) settings.penalty_growth = atof(getenv("GROW"));
  if (getenv("KPTS")) settings.grid_points = atoi(getenv("KPTS"));
  ToppReport report;
  ToppSolver solver(settings);
  auto t0 = std::chrono::steady_clock::now();
  auto r = solver.solve(path, elevatorDrive(), armDrive(), b_start, &report);
  auto t1 = std::chrono::steady_clock::now();
  FineReference ref(*path, elevatorDrive(), armDrive(), 2001);
  const double tref = ref.duration(b_start);
  std::printf("%-12s L=%.3f ok=%d T=%.4f ref=%.4f ratio=%.4f fb=%.4f outer=%d inner=%d evals=%d ref=%d pr=%.2g du=%.2g rho=%.3g pV=%.4f pI=%.4f %.2f ms %s\n",
              name, path->length(), r.ok(), r.ok() ? r.value().duration_s() : -1.0, tref,
              r.ok() ? r.value().duration_s() / tref : -1.0, report.warm_start_duration_s, report.outer_iterations,
              report.inner_iterations, report.evaluations, report.refinements, report.primal_residual,
              report.dual_residual, report.penalty, report.peak_voltage_ratio, report.peak_current_ratio,
              std::chrono::duration<double, std::milli>(t1 - t0).count(), r.ok() ? "" : r.error().reason.c_str());
}

TEST(ToppScratch, Print) {
  run("line-elev", std::make_shared<LinePath>(JointVector(0.2, 1.57), JointVector(1.97, 1.57)), 0.0);
  run("line-both", std::make_shared<LinePath>(JointVector(0.2, 1.57), JointVector(1.97, 5.17)), 0.0);
  run("line-down", std::make_shared<LinePath>(JointVector(1.97, 5.17), JointVector(0.16, 0.10)), 0.0);
  run("arm-only", std::make_shared<LinePath>(JointVector(0.5, 0.1), JointVector(0.5, 6.0)), 0.0);
  run("arc", std::make_shared<ArcPath>(JointVector(1.0, 3.0), 0.8, 0.0, 3.0), 0.0);
  run("wiggle", std::make_shared<WigglePath>(JointVector(0.2, 1.0), JointVector(1.5, 4.0), JointVector(0.05, 0.8), 3.0, 2.0), 0.0);
  run("short", std::make_shared<LinePath>(JointVector(0.5, 1.0), JointVector(0.51, 1.0)), 0.0);
  run("moving", std::make_shared<LinePath>(JointVector(0.2, 1.57), JointVector(1.97, 1.57)), 1.0);
}
}  // namespace
}  // namespace cyber::planner
namespace cyber::planner {
namespace {
TEST(ToppScratch, Wiggle) {
  run("wiggle", std::make_shared<testing::WigglePath>(JointVector(0.2, 1.0), JointVector(1.5, 4.0), JointVector(0.05, 0.8), 3.0, 2.0), 0.0);
}
TEST(ToppScratch, Short2) {
  run("short2", std::make_shared<testing::LinePath>(JointVector(0.5, 1.0), JointVector(0.6, 1.2)), 0.0);
}
}  // namespace
}  // namespace cyber::planner
#include "cyber/planner/topp_reachability.hpp"
namespace cyber::planner {
namespace {
TEST(ToppScratch, HessianCheck) {
  auto path = std::make_shared<testing::WigglePath>(JointVector(0.2, 1.0), JointVector(1.5, 4.0), JointVector(0.05, 0.8), 3.0, 2.0);
  topp::Problem problem;
  topp::LimitMargins margins;
  topp::sampleGrid(*path, 200, problem);
  margins.reset(problem.intervals());
  const std::array<DriveParams, 2> drives{testing::elevatorDrive(), testing::armDrive()};
  topp::buildRows(drives, margins, problem, nullptr);
  std::vector<double> b, c;
  topp::forwardBackward(problem, b, c);
  Eigen::VectorXd x;
  topp::initialGuess(problem, b, x);
  problem.cost_scale = 1.0 / 0.6777;
  topp::Multipliers m;
  topp::estimateMultipliers(problem, x, m);
  const double rho = 1000.0;
  BandedCholesky h;
  topp::assembleHessian(problem, m, rho, x, h);
  Eigen::VectorXd g0(x.size()), g1(x.size());
  topp::augmentedLagrangian(problem, m, rho, x, g0);
  std::mt19937 rng(3);
  std::normal_distribution<double> nd;
  for (double eps : {1e-6, 1e-8}) {
    Eigen::VectorXd d(x.size());
    for (int i = 0; i < d.size(); ++i) d[i] = nd(rng);
    Eigen::VectorXd xe = x + eps * d;
    topp::augmentedLagrangian(problem, m, rho, xe, g1);
    Eigen::VectorXd fd = (g1 - g0) / eps;
    Eigen::VectorXd hd = Eigen::VectorXd::Zero(x.size());
    for (int i = 0; i < x.size(); ++i)
      for (int j = std::max(0, i - 6); j <= std::min<int>(x.size() - 1, i + 6); ++j) hd[i] += h.entry(i, j) * d[j];
    Eigen::Index at;
    (fd - hd).cwiseAbs().maxCoeff(&at);
    { Eigen::Index mi; m.speed_square.cwiseAbs().maxCoeff(&mi); std::printf("max |nu| %.4g at node %ld; nu at 6 %.4g at 198 %.4g; c at 6 %.4g\n", m.speed_square[mi], (long)mi, m.speed_square[6], m.speed_square[198], x[26]); }
    std::printf("eps %g |fd| %.4g |hd| %.4g |diff| %.4g max diff at %ld (node %ld slot %ld): fd %.6g hd %.6g\n", eps, fd.norm(), hd.norm(), (fd - hd).norm(), (long)at, (long)at / 4, (long)at % 4, fd[at], hd[at]);
  }
}
}  // namespace
}  // namespace cyber::planner
namespace cyber::planner {
namespace {
TEST(ToppScratch, ShortOnly) {
  run("short", std::make_shared<testing::LinePath>(JointVector(0.5, 1.0), JointVector(0.51, 1.0)), 0.0);
}
}  // namespace
}  // namespace cyber::planner
