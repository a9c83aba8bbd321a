#include "plan_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "cyber/planner.hpp"

namespace cyber::tools {
namespace {

constexpr double kPrintedTimeS = 1e-6;  // t is printed with six decimals (writeTrajectoryCsv)

// Sample times 0, step, 2 step, ... and the exact end, so the last row is the goal at rest.
std::vector<double> sampleTimes(const planner::Trajectory& trajectory, double step_s) {
  const double duration = trajectory.duration_s();
  const long steps = static_cast<long>(std::floor(duration / step_s + 1e-9));
  const double remainder = duration - static_cast<double>(steps) * step_s;
  // An end less than the printed microsecond past the last step would print that step's time
  // again (times must increase): the end then takes that step's place.
  const long last = remainder > 1e-9 && remainder < kPrintedTimeS && steps > 0 ? steps - 1 : steps;
  std::vector<double> times_s;
  times_s.reserve(static_cast<size_t>(last) + 2);
  for (long k = 0; k <= last; ++k) times_s.push_back(static_cast<double>(k) * step_s);
  if (remainder > 1e-9) times_s.push_back(duration);
  return times_s;
}

template <class F>
void forEachSample(const planner::Trajectory& trajectory, double step_s, F&& f) {
  for (const double t : sampleTimes(trajectory, step_s)) f(trajectory.sample(t));
}

// Why samples `step_s` apart do not describe the trajectory, or kNone when they do.
FinerCsvReason undescribedAt(const planner::Trajectory& trajectory, const planner::MotionSettings& settings,
                             double step_s) {
  if (!planner::columnsAgree(settings, trajectory, step_s)) return FinerCsvReason::kColumns;
  const std::optional<double> ride = planner::fastestRideAlongSamples(trajectory, sampleTimes(trajectory, step_s));
  if (!ride || trajectory.duration_s() > (1.0 + kCsvRideShare) * *ride) return FinerCsvReason::kRide;
  return FinerCsvReason::kNone;
}

}  // namespace

CsvSpacing csvSpacingFor(const planner::Trajectory& trajectory, const planner::MotionSettings& settings) {
  CsvSpacing spacing;
  spacing.reason = undescribedAt(trajectory, settings, kCsvStepS);
  if (spacing.reason == FinerCsvReason::kNone) return spacing;
  spacing.step_s = kMinCsvStepS;
  for (const double step_s : std::span(kCsvSteps).subspan(1)) {
    if (undescribedAt(trajectory, settings, step_s) == FinerCsvReason::kNone) {
      spacing.step_s = step_s;
      break;
    }
  }
  return spacing;
}

std::string finerCsvMessage(const CsvSpacing& spacing) {
  const std::string why =
      spacing.reason == FinerCsvReason::kColumns
          ? std::string("its acceleration or velocity column would not integrate to the one above it")
          : fmt::format(
                "a ride along its samples would be more than {:g} % faster than the plan, passing where "
                "the path's tangent goes to zero faster than the motors can",
                100 * kCsvRideShare);
  return fmt::format(
      "cyber-plan: the CSV's samples are {:g} ms apart: at {:g} ms {} (docs/moving-starts.md, \"The CSV's "
      "spacing\")",
      spacing.step_s * 1e3, kCsvStepS * 1e3, why);
}

Result<Done, PlanOutputStatus> writeTrajectoryCsv(const planner::Trajectory& trajectory,
                                                  const planner::JointChain& joints, const std::string& path,
                                                  double step_s) {
  using Written = Result<Done, PlanOutputStatus>;
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!file) return Written::failure(PlanOutputStatus::kCannotWrite, path + ": cannot open for writing");
  std::fputs("t", file.get());
  for (const planner::ChainJoint& joint : joints) {
    for (const char* column : plot::kCsvColumns)
      std::fprintf(file.get(), ",%s", plot::csvColumn(joint.name, column).c_str());
  }
  std::fputs("\n", file.get());
  forEachSample(trajectory, step_s, [&](const planner::TrajectorySample& s) {
    std::fprintf(file.get(), "%.6f", s.t);
    for (int j = 0; j < s.q.size(); ++j) {
      std::fprintf(file.get(), ",%.9g,%.9g,%.9g,%.9g,%.9g", s.q[j], s.qdot[j], s.qddot[j], s.volts[j], s.amps[j]);
    }
    std::fputs("\n", file.get());
  });
  if (std::ferror(file.get()) != 0) return Written::failure(PlanOutputStatus::kCannotWrite, path + ": write failed");
  return Done{};
}

std::string planSummaryJson(const planner::Plan& plan) {
  const auto& t = plan.times_ms;
  const auto& r = plan.solver;
  return fmt::format(
      "{{\"status\":\"ok\",\"duration_s\":{:.9g},\"grid_ms\":{:.9g},\"search_ms\":{:.9g},\"smooth_ms\":{:.9g},"
      "\"topp_ms\":{:.9g},\"total_ms\":{:.9g},\"primal_residual\":{:.9g},\"dual_residual\":{:.9g},"
      "\"outer_iterations\":{},\"inner_iterations\":{},\"min_clearance_m\":{:.9g},\"waypoints\":{},"
      "\"method\":\"{}\"}}",
      plan.trajectory->duration_s(), t.grid, t.search, t.smooth, t.topp, t.total, r.primal_residual, r.dual_residual,
      r.outer_iterations, r.inner_iterations, plan.min_clearance_m, plan.waypoints.size(), plan.method.name());
}

plot::TrajectoryPlotData plotDataOf(const planner::Plan& plan, const planner::RobotModel& robot, int scene,
                                    planner::HeldPieces pieces, const std::string& title) {
  plot::TrajectoryPlotData d;
  d.title = title;
  d.joints.resize(static_cast<size_t>(robot.jointCount()));
  forEachSample(*plan.trajectory, kCsvStepS, [&](const planner::TrajectorySample& s) {
    d.time_s.push_back(s.t);
    for (size_t j = 0; j < d.joints.size(); ++j) {
      const auto i = static_cast<Eigen::Index>(j);
      plot::JointSeries& series = d.joints[j];
      series.position.push_back(s.q[i]);
      series.velocity.push_back(s.qdot[i]);
      series.volts.push_back(s.volts[i]);
      series.amps.push_back(s.amps[i]);
    }
  });
  plot::addRobotView(d, robot, scene, pieces);
  return d;
}

}  // namespace cyber::tools
