#pragma once
// The simulator's event loop: CAN setpoints in, the plant stepped to each event's time, ARM_STATE
// and the heartbeat out on timers, faults from the schedule. Single-threaded, epoll on a CAN
// socket, three timerfds and a signalfd; it sleeps between events.

#include <array>
#include <cstdio>
#include <memory>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "cyber/can/can_socket.hpp"
#include "cyber/plant/fault_schedule.hpp"
#include "cyber/plant/plant_simulation.hpp"
#include "cyber/plant/sim_options.hpp"

namespace cyber::plant {

struct RunnerSetup {
  SimOptions options;
  SimulationSettings simulation;
  std::array<std::uint8_t, 2> joint_devices{1, 2};             // setpoint frames of joint 0 and joint 1
  std::array<std::string, 2> joint_names{"joint0", "joint1"};  // the config's, for the closing line
  std::array<std::string, 2> joint_units{"m", "rad"};
  std::string state_channel = "ARM_STATE";
  std::string can_interface;
};

struct RunCounters {
  long setpoints[kJointCount] = {0, 0};
  long sequence_gaps = 0;  // setpoint sequence bytes that did not follow the previous one
  long malformed = 0;      // our setpoint ids with a payload the codec rejects
  long other_frames = 0;   // anything else that passed the receive filter
  long bus_errors = 0;     // controller error frames
  long read_failures = 0;  // socket read errors (e.g. ENETDOWN while the link is down)
  long heartbeats_sent = 0;
  long disables_sent = 0;
  long write_failures = 0;  // heartbeat / disable writes that failed
  long states_published = 0;
  long publish_failures = 0;
};

// Runs until SIGINT/SIGTERM, --duration or an exit fault. control_fd: the --control FIFO opened
// read-write and non-blocking, or -1. Returns the process exit status.
int runSimulator(const RunnerSetup& setup, can::CanSocket socket, lcm::LCM& lcm, std::FILE* log, int control_fd);

}  // namespace cyber::plant
