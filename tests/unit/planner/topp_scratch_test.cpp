#include <chrono>
#include <cstdio>
#include <cstdlib>

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
TEST(ToppScratch, Short2) {
  run("short2", std::make_shared<testing::LinePath>(JointVector(0.5, 1.0), JointVector(0.6, 1.2)), 0.0);
}
}  // namespace
}  // namespace cyber::planner
