// Writes an LCM log with one ARM_TRAJECTORY (request 42, a 1 s sine move) and one garbage event,
// as lcm-logger would record them, for the cyber-plot test.
#include <lcm/lcm-cpp.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

#include "cyberplanner/arm_trajectory_t.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_trajectory_log FILE\n");
    return 2;
  }
  lcm::LogFile log(argv[1], "w");
  if (!log.good()) return 1;
  cyberplanner::arm_trajectory_t m{};
  m.request_id = 42;
  m.duration_s = 1.0;
  m.dt_s = 0.01;
  m.num_samples = 101;
  // position, velocity and volts are [joint][sample].
  m.num_joints = 2;  // the reference robot's elevator and arm
  for (auto* table : {&m.position, &m.velocity, &m.volts}) table->resize(2);
  for (int k = 0; k < m.num_samples; ++k) {
    const double t = k * m.dt_s;
    m.t_s.push_back(t);
    m.position[0].push_back(0.2 + 0.5 * (1 - std::cos(M_PI * t)));
    m.velocity[0].push_back(0.5 * M_PI * std::sin(M_PI * t));
    m.position[1].push_back(1.57 + 1.0 * (1 - std::cos(M_PI * t)));
    m.velocity[1].push_back(M_PI * std::sin(M_PI * t));
    m.volts[0].push_back(0.37 + 3.93 * m.velocity[0].back());
    m.volts[1].push_back(0.21 * std::cos(m.position[1].back()) + 1.18 * m.velocity[1].back());
  }
  std::vector<char> buffer(static_cast<size_t>(m.getEncodedSize()));
  m.encode(buffer.data(), 0, static_cast<int>(buffer.size()));
  char garbage[7] = {1, 2, 3, 4, 5, 6, 7};
  lcm::LogEvent events[2] = {};
  events[0].channel = "ARM_TRAJECTORY";
  events[0].data = garbage;
  events[0].datalen = sizeof garbage;
  events[1].channel = "ARM_TRAJECTORY";
  events[1].data = buffer.data();
  events[1].datalen = static_cast<int32_t>(buffer.size());
  for (int i = 0; i < 2; ++i) {
    events[i].eventnum = i;
    events[i].timestamp = 1000000 + i;
    if (log.writeEvent(&events[i]) != 0) return 1;
  }
  return 0;
}
