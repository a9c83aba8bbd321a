#include "trajectory_sources.hpp"

#include <lcm/lcm-cpp.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "cyber/lcmtypes/safe_decode.hpp"
#include "cyber/plot/trajectory_csv.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"

namespace cyber::tools {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) out.push_back(cell);
  return out;
}

Error<SourceStatus> sourceError(SourceStatus status, const std::string& path, const std::string& what) {
  return {status, path + ": " + what};
}

}  // namespace

Result<plot::TrajectoryPlotData, SourceStatus> readPlanCsv(const std::string& path, const planner::JointChain& joints) {
  if (joints.empty()) return sourceError(SourceStatus::kMalformed, path, "the robot has no joints to read");
  std::ifstream in(path);
  if (!in) return sourceError(SourceStatus::kCannotOpen, path, "cannot open");
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line);
  std::map<std::string, size_t> column;
  for (size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
  // Per joint: position, velocity, volts, amps (the plot needs no acceleration).
  std::vector<std::string> needed{"t"};
  for (const planner::ChainJoint& joint : joints) {
    for (const char* c : {"pos", "vel", "volts", "amps"}) needed.push_back(plot::csvColumn(joint.name, c));
  }
  for (const std::string& name : needed) {
    if (!column.contains(name)) {
      return sourceError(SourceStatus::kMalformed, path,
                         "no column \"" + name + "\" (expected cyber-plan --csv output for this robot)");
    }
  }
  plot::TrajectoryPlotData data;
  data.joints.resize(static_cast<size_t>(joints.size()));
  std::vector<double> values(needed.size());
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line);
    auto value = [&](const std::string& name, double* out) {
      const size_t i = column[name];
      char* end = nullptr;
      if (i >= cells.size()) return false;
      *out = std::strtod(cells[i].c_str(), &end);
      return end != cells[i].c_str() && *end == '\0' && std::isfinite(*out);
    };
    for (size_t i = 0; i < needed.size(); ++i) {
      if (!value(needed[i], &values[i])) {
        return sourceError(SourceStatus::kMalformed, path + ":" + std::to_string(row), "not a row of finite numbers");
      }
    }
    data.time_s.push_back(values[0]);
    for (size_t j = 0; j < data.joints.size(); ++j) {
      const double* joint = values.data() + 1 + 4 * j;
      data.joints[j].position.push_back(joint[0]);
      data.joints[j].velocity.push_back(joint[1]);
      data.joints[j].volts.push_back(joint[2]);
      data.joints[j].amps.push_back(joint[3]);
    }
  }
  if (data.time_s.empty()) return sourceError(SourceStatus::kNoTrajectory, path, "no samples");
  return data;
}

Result<plot::TrajectoryPlotData, SourceStatus> readTrajectoryFromLog(const std::string& path,
                                                                     const std::string& channel,
                                                                     std::optional<int64_t> request_id,
                                                                     const planner::RobotModel& robot) {
  lcm::LogFile log(path, "r");
  if (!log.good()) return sourceError(SourceStatus::kCannotOpen, path, "cannot open the LCM log");
  std::optional<cyberplanner::arm_trajectory_t> chosen;
  int undecodable = 0;
  for (const lcm::LogEvent* event = log.readNextEvent(); event != nullptr; event = log.readNextEvent()) {
    if (event->channel != channel) continue;
    cyberplanner::arm_trajectory_t message{};
    if (lcmtypes::safeDecode(message, event->data, event->datalen) < 0) {
      ++undecodable;
      continue;
    }
    if (!request_id || message.request_id == *request_id) chosen = std::move(message);
  }
  if (!chosen) {
    return sourceError(SourceStatus::kNoTrajectory, path,
                       std::string("no ") + (request_id ? "matching " : "") + "message on " + channel +
                           (undecodable > 0 ? " (" + std::to_string(undecodable) + " undecodable)" : ""));
  }
  const cyberplanner::arm_trajectory_t& m = *chosen;
  // Rows by the config's [[joints]] order (docs/lcm.md, "Joints by index"): a trajectory of
  // another joint count is of another robot.
  if (m.num_joints != robot.jointCount()) {
    return sourceError(SourceStatus::kNoTrajectory, path,
                       std::string("the trajectory has ")
                           .append(std::to_string(m.num_joints))
                           .append(" joints, the robot description ")
                           .append(std::to_string(robot.jointCount())));
  }
  plot::TrajectoryPlotData data;
  data.joints.resize(static_cast<size_t>(m.num_joints));
  for (int k = 0; k < m.num_samples; ++k) {
    const size_t i = static_cast<size_t>(k);
    data.time_s.push_back(m.t_s[i]);
    // position, velocity and volts are [joint][sample] (safeDecode checked the sizes).
    for (int j = 0; j < m.num_joints; ++j) {
      const auto row = static_cast<size_t>(j);
      const double v = m.velocity[row][i];
      const double volts = m.volts[row][i];
      plot::JointSeries& series = data.joints[row];
      series.position.push_back(m.position[row][i]);
      series.velocity.push_back(v);
      series.volts.push_back(volts);
      series.amps.push_back(robot.drive(j).amps(volts, v));
    }
  }
  if (data.time_s.empty()) return sourceError(SourceStatus::kNoTrajectory, path, "the trajectory has no samples");
  data.title = "ARM_TRAJECTORY request " + std::to_string(m.request_id);
  return data;
}

}  // namespace cyber::tools
