#pragma once
// The simulator's event loop: CAN setpoints in, the plant stepped to each event's time, ARM_STATE
// and the heartbeat out on timers, faults from the schedule. Single-threaded, epoll on a CAN
// socket, three timerfds and a signalfd; it sleeps between events.

#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "cyber/can/can_socket.hpp"
#include "cyber/plant/fault_schedule.hpp"
#include "cyber/plant/plant_simulation.hpp"
#include "cyber/plant/sim_options.hpp"

namespace cyber::plant {

// One entry per joint of the simulated plant (simulation.plant.jointCount()), chain order.
struct RunnerSetup {
  SimOptions options;
  SimulationSettings simulation;
  planner::PerJoint<std::uint8_t> joint_devices;  // the device number of each joint's setpoint frames
  planner::PerJoint<std::string> joint_names;     // the config's, for the log lines
  planner::PerJoint<std::string> joint_units;     // m or rad
  std::string state_channel = "ARM_STATE";
  std::string can_interface;
};

// The setpoint frames per joint and their sequence gaps are counted by JointStreams.
struct RunCounters {
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
