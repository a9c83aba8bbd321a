// A drawn robot as the TOML of docs/configuration.md. Numbers are written with fmt's shortest
// form that reads back as the same double, so the file loads as the robot that was drawn.
#include <fmt/format.h>

#include <set>
#include <string>

#include "random_robot_draws.hpp"

namespace cyber::test::random_robot {
namespace {

using planner::JointType;
using planner::Point2;

std::string num(double x) { return fmt::format("{}", x); }
std::string point(const Point2& p) { return fmt::format("[{}, {}]", p.x(), p.y()); }
// One entry per joint.
std::string joints(const planner::JointVector& v) {
  std::string out = "[";
  for (int j = 0; j < v.size(); ++j) out.append(j == 0 ? "" : ", ").append(num(v[j]));
  return out.append("]");
}

std::string polygon(const Polygon& polygon) {
  std::string out = "[";
  for (size_t i = 0; i < polygon.size(); ++i) out.append(i == 0 ? "" : ", ").append(point(polygon[i]));
  return out.append("]");
}

std::string polygons(const std::vector<Polygon>& list) {
  std::string out = "[\n";
  for (const Polygon& p : list) out.append("  ").append(polygon(p)).append(",\n");
  return out.append("]\n");
}

std::string body(const Body& b) {
  return fmt::format("mass_kg = {}\ncg_m = {}\nmoi_kgm2 = {}\n", b.mass_kg, point(b.cg_m), b.moi_kgm2);
}

std::string chain(const RobotDraw& robot) {
  std::string out;
  for (const JointDraw& j : robot.joints) {
    out.append(
        fmt::format("[[joints]]\nname = \"{}\"\ntype = \"{}\"\nmin = {}\nmax = {}\norigin_m = {}\naxis_deg = {}\n\n",
                    j.name, j.type == JointType::kPrismatic ? "prismatic" : "revolute", j.range.min, j.range.max,
                    point(j.origin_m), j.axis_deg));
  }
  for (const JointDraw& j : robot.joints) {
    out.append(fmt::format("[links.{}_link]\njoint = \"{}\"\npolygons = {}\n", j.name, j.name, polygons(j.outline)));
  }
  for (const PieceDraw& p : robot.pieces) {
    out.append(fmt::format("[pieces.{}]\njoint = \"{}\"\npolygons = {}", p.name, robot.joints.back().name,
                           polygons({p.polygon})));
    if (robot.rigid_body) out.append(body(p.body));
    out.append("\n");
  }
  return out;
}

std::string scene(const SceneDraw& scene) {
  std::string out = "[obstacles]\n", fixed, elements;
  for (const NamedPolygonDraw& o : scene.fixed) {
    out.append(fmt::format("{} = {}\n", o.name, polygon(o.polygon)));
    fixed.append(fixed.empty() ? "" : ", ").append("\"" + o.name + "\"");
  }
  for (const NamedPolygonDraw& o : scene.elements) {
    out.append(fmt::format("{} = {}\n", o.name, polygon(o.polygon)));
    elements.append(elements.empty() ? "" : ", ").append("\"" + o.name + "\"");
  }
  return out +
         fmt::format("\n[[scenes]]\nname = \"field\"\nobstacles = [{}]\nfixed = [{}]\noffset_range_m = [{}, {}]\n\n",
                     elements, fixed, scene.offset_range_m.min, scene.offset_range_m.max);
}

std::string drive(const RobotDraw& robot, size_t j) {
  const DriveDraw& d = robot.drives[j];
  std::string out = fmt::format(
      "[drives.{}]\nkind = \"{}\"\nmotor = \"{}\"\ncount = {}\ngearing = {}\nkS_volts = {}\nvoltage_limit_volts = "
      "{}\ncurrent_limit_amps = {}\n",
      robot.joints[j].name, robot.rigid_body ? "rigid_body" : "feedforward", d.motor->key, d.count, d.gearing,
      d.kS_volts, d.voltage_limit_volts, d.current_limit_amps);
  if (d.velocity_limit) out.append(fmt::format("velocity_limit = {}\n", *d.velocity_limit));
  if (d.acceleration_limit) out.append(fmt::format("acceleration_limit = {}\n", *d.acceleration_limit));
  if (robot.rigid_body) return out + body(robot.joints[j].body) + "\n";
  return out + fmt::format("gravity = \"{}\"\nkG_volts = {}\nkV = {}\nkA = {}\n\n", d.gravity, d.kG_volts, d.kV, d.kA);
}

std::string drives(const RobotDraw& robot) {
  std::string out;
  std::set<std::string> written;
  for (const DriveDraw& d : robot.drives) {
    if (!written.insert(d.motor->key).second) continue;
    out.append(fmt::format(
        "[motors.{}]\nnominal_voltage_volts = 12.0\nstall_torque_nm = {}\nstall_current_amps = {}\nfree_current_amps = "
        "{}\nfree_speed_rpm = {}\n\n",
        d.motor->key, d.motor->stall_torque_nm, d.motor->stall_current_amps, d.motor->free_current_amps,
        d.motor->free_speed_rpm));
  }
  for (size_t j = 0; j < robot.drives.size(); ++j) out.append(drive(robot, j));
  return out;
}

std::string planner(const planner::PlannerSettings& s) {
  const planner::SmoothingSettings& m = s.smoothing;
  const planner::ToppSettings& t = s.topp;
  return fmt::format(
      "[planner]\nmetric = {}\n\n[planner.grid]\nstep = {}\n\n[planner.search]\npotential_weight = {}\n"
      "potential_range = {}\noffset_band_clearances = {}\n\n[planner.smoothing]\nwaypoint_spacing = {}\n"
      "obstacle_weight = {}\nobstacle_decay_m = {}\nprior_weight = {}\nlength_weight = {}\nsmoothness_weight = {}\n"
      "max_iterations = {}\ngradient_tolerance = {}\nrelative_cost_tolerance = {}\nlead_in_time_s = {}\n"
      "max_lead_in = {}\n\n[planner.topp]\ngrid_points = {}\nprimal_tolerance = {}\ndual_tolerance = {}\n"
      "max_outer_iterations = {}\nmax_inner_iterations = {}\nlimit_check_step_s = {}\nlimit_check_tolerance = {}\n"
      "max_limit_refinements = {}\npenalty_initial = {}\npenalty_growth = {}\npenalty_max = {}\n\n",
      joints(s.metric), joints(s.grid.step), s.search.potential_weight, s.search.potential_range,
      s.search.offset_band_clearances, m.waypoint_spacing, m.obstacle_weight, m.obstacle_decay_m, m.prior_weight,
      m.length_weight, m.smoothness_weight, m.max_iterations, m.gradient_tolerance, m.relative_cost_tolerance,
      m.lead_in_time_s, m.max_lead_in, t.grid_points, t.solver.primal_tolerance, t.solver.dual_tolerance,
      t.solver.max_outer_iterations, t.solver.max_inner_iterations, t.limit_check_step_s, t.limit_check_tolerance,
      t.max_limit_refinements, t.solver.penalty_initial, t.solver.penalty_growth, t.solver.penalty_max);
}

// The reference robot's daemon settings; only the device numbers depend on the joints.
std::string daemon(const RobotDraw& robot) {
  std::string devices;
  for (size_t j = 0; j < robot.joints.size(); ++j)
    devices.append(fmt::format("{} = {}\n", robot.joints[j].name, j + 1));
  return fmt::format(
      "[daemon]\nlcm_url = \"udpm://239.255.76.67:5810?ttl=0\"\ncan_interface = \"can0\"\nstream_rate_hz = 200.0\n"
      "state_timeout_s = 0.25\nheartbeat_timeout_s = 0.1\nrequire_robot_enabled = true\nplanning_budget_s = 0.03\n"
      "status_rate_hz = 10.0\nsetpoint_echo_rate_hz = 50.0\ntrajectory_step_s = 0.01\nlog_level = \"info\"\n\n"
      "[daemon.devices]\n{}status = {}\n\n[daemon.channels]\ngoal = \"ARM_GOAL\"\nstate = \"ARM_STATE\"\n"
      "plan_status = \"ARM_PLAN_STATUS\"\ntrajectory = \"ARM_TRAJECTORY\"\nsetpoint = \"ARM_SETPOINT\"\n"
      "daemon_status = \"ARM_DAEMON_STATUS\"\n",
      devices, robot.joints.size() + 1);
}

}  // namespace

std::string robotToml(const RobotDraw& robot, const std::string& poses) {
  std::string out = fmt::format("# {}\n# {}\n\nname = \"{}\"\nclearance_m = {}\n\n", robot.name, robot.summary,
                                robot.name, num(robot.clearance_m));
  out.append(chain(robot)).append(scene(robot.scene)).append(drives(robot)).append(planner(robot.planner));
  return out.append(poses).append(daemon(robot));
}

}  // namespace cyber::test::random_robot
