#include "read_planner.hpp"

#include <fmt/format.h>

#include "cyber/config/derived_defaults.hpp"
#include "setting_reader.hpp"

namespace cyber::config::detail {
namespace {

constexpr SettingSource kDerived = SettingSource::kDerived;

void readSmoothing(TableReader g, planner::SmoothingSettings& s, std::vector<SettingOrigin>& log) {
  SettingReader r(g, log);
  r.number("waypoint_spacing", s.waypoint_spacing, Bounds{1e-3, 1.0});
  r.number("obstacle_weight", s.obstacle_weight, kNonNegative);
  r.number("obstacle_decay_m", s.obstacle_decay_m, kPositive);
  r.number("prior_weight", s.prior_weight, kNonNegative);
  r.number("length_weight", s.length_weight, kNonNegative);
  r.number("smoothness_weight", s.smoothness_weight, kNonNegative);
  r.integer("max_iterations", s.max_iterations, 0, 100000);
  r.number("gradient_tolerance", s.gradient_tolerance, kPositive);
  r.number("relative_cost_tolerance", s.relative_cost_tolerance, Bounds{0.0, 1.0});
  r.number("lead_in_time_s", s.lead_in_time_s, Bounds{0.0, 1.0});
  r.number("max_lead_in", s.max_lead_in, Bounds{0.0, 2.0});
  g.finish();
}

void readTopp(TableReader g, planner::ToppSettings& s, std::vector<SettingOrigin>& log) {
  SettingReader r(g, log);
  r.integer("grid_points", s.grid_points, 8, 100000);
  r.number("primal_tolerance", s.solver.primal_tolerance, kPositive);
  r.number("dual_tolerance", s.solver.dual_tolerance, kPositive);
  r.integer("max_outer_iterations", s.solver.max_outer_iterations, 1, 100000);
  r.integer("max_inner_iterations", s.solver.max_inner_iterations, 1, 1000000);
  r.number("limit_check_step_s", s.limit_check_step_s, Bounds{1e-5, 0.01});
  r.number("limit_check_tolerance", s.limit_check_tolerance, Bounds{0.0, 0.1});
  r.integer("max_limit_refinements", s.max_limit_refinements, 0, 100);
  r.number("penalty_initial", s.solver.penalty_initial, kPositive);
  r.number("penalty_growth", s.solver.penalty_growth, kNonNegative);
  r.number("penalty_max", s.solver.penalty_max, Bounds{s.solver.penalty_initial, 1e300});
  if (s.solver.penalty_max < s.solver.penalty_initial) {
    g.fail("penalty_max",
           fmt::format("left at its default {:g}, below penalty_initial: give it", s.solver.penalty_max));
  }
  g.finish();
}

}  // namespace

void readPlanner(TableReader p, planner::RobotModel& robot, std::vector<SettingOrigin>& log) {
  planner::PlannerSettings& s = robot.planner;
  const DerivedPlannerDefaults derived = derivePlannerDefaults(robot);
  s.metric = derived.metric;
  s.grid.step = derived.grid_step;
  s.search.potential_range = derived.potential_range;
  SettingReader r(p, log);
  r.jointVector("metric", s.metric, kPositive, kDerived);
  {
    TableReader g = p.optionalTable("grid");
    SettingReader(g, log).jointVector("step", s.grid.step, Bounds{1e-4, 0.5}, kDerived);
    g.finish();
  }
  {
    TableReader g = p.optionalTable("search");
    SettingReader search(g, log);
    search.number("potential_weight", s.search.potential_weight, kNonNegative);
    search.number("potential_range", s.search.potential_range, kPositive, kDerived);
    search.number("offset_band_clearances", s.search.offset_band_clearances, Bounds{0.5, 20.0});
    g.finish();
  }
  readSmoothing(p.optionalTable("smoothing"), s.smoothing, log);
  readTopp(p.optionalTable("topp"), s.topp, log);
  p.finish();
}

}  // namespace cyber::config::detail
