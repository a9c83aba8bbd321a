// cyber-plant-sim: the motor controller of each of a robot's joints and their mechanism, simulated
// on a CAN interface for tests (docs/testing.md, "Plant simulator"). `cyber-plant-sim --help`
// lists the options; sim_runner.cpp is the event loop, cyber/plant/mechanism_plant.hpp the model.

#include <sys/stat.h>
#include <fcntl.h>
#include <pthread.h>
#include <sched.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/can/frc_id.hpp"
#include "cyber/can/id_filter.hpp"
#include "cyber/cli/usage_exit.hpp"
#include "cyber/config/load_config.hpp"
#include "cyber/plant/sim_options.hpp"
#include "cyber/plant/state_log.hpp"
#include "sim_runner.hpp"

namespace {

using cyber::plant::SimOptions;

bool validDevice(int device) { return device >= 0 && device <= cyber::can::kMaxDeviceNumber; }

// Where the joints rest before their first setpoint unless --initial says: the config's first
// named pose (a robot's stowed pose by convention), else the middle of every range.
cyber::planner::JointVector defaultInitialPose(const cyber::config::Config& config) {
  for (const cyber::config::PoseSet& set : config.poses) {
    if (!set.poses.empty()) return set.poses.front().q;
  }
  const auto& robot = config.robot;
  cyber::planner::JointVector middle(robot.jointCount());
  for (int j = 0; j < robot.jointCount(); ++j) middle[j] = 0.5 * (robot.range(j).min + robot.range(j).max);
  return middle;
}

// "Q0,Q1,..." as --initial takes it, for messages.
std::string jointList(const cyber::planner::JointVector& q) {
  std::string out;
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    if (j > 0) out += ',';
    out += std::to_string(q[j]);
  }
  return out;
}

// The config's joints for messages: "2 joints (elevator, arm)".
std::string jointNames(const cyber::planner::RobotModel& robot) {
  std::string names;
  for (const cyber::planner::ChainJoint& joint : robot.joints) names += (names.empty() ? "" : ", ") + joint.name;
  const int n = robot.jointCount();
  return std::to_string(n) + (n == 1 ? " joint (" : " joints (") + names + ")";
}

// Refuses an --initial without one value per joint or outside the ranges, gains for a joint the
// config does not have, an unknown piece and a bad [daemon.devices]: the exit status to leave
// with, or none when the options hold.
std::optional<int> refusedOptions(const cyber::config::Config& config, const SimOptions& options,
                                  const cyber::planner::JointVector& initial_q,
                                  const cyber::cli::ProgramUsage& program) {
  const auto& robot = config.robot;
  const int joints = robot.jointCount();
  if (initial_q.size() != joints) {
    return cyber::cli::reportBadUsage(
        program, cyber::cli::badUsage("--initial " + jointList(initial_q) + ": " + robot.name + " has " +
                                      jointNames(robot) + ", one value each"));
  }
  if (!robot.withinLimits(initial_q)) {
    return cyber::cli::reportBadUsage(program, cyber::cli::badUsage("--initial " + jointList(initial_q) +
                                                                    " is outside the joint ranges of " + robot.name));
  }
  for (int j = joints; j < cyber::plant::kMaxJoints; ++j) {
    if (options.joint_gains[static_cast<size_t>(j)]) {
      return cyber::cli::reportBadUsage(
          program,
          cyber::cli::badUsage("--joint" + std::to_string(j) + "-gains: " + robot.name + " has " + jointNames(robot)));
    }
  }
  for (const std::string& piece : options.pieces) {
    if (const auto named = robot.piecesNamed(piece); !named) {
      return cyber::cli::reportBadUsage(program, cyber::cli::badUsage("--pieces: " + named.error().message));
    }
  }
  // The loader checks these too; the simulator relies on them for its frame filter and lookup.
  const std::vector<int>& devices = config.daemon.devices.joints;
  bool devices_ok = devices.size() == static_cast<size_t>(joints);
  for (size_t j = 0; j < devices.size() && devices_ok; ++j) {
    devices_ok = validDevice(devices[j]);
    for (size_t k = 0; k < j && devices_ok; ++k) devices_ok = devices[k] != devices[j];
  }
  if (!devices_ok) {
    std::cerr << "cyber-plant-sim: [daemon.devices] of " << robot.name << "'s " << jointNames(robot)
              << " must be distinct numbers 0..63, one per joint\n";
    return 2;
  }
  return std::nullopt;
}

// What the simulator runs: devices, names and units of the joints, the channels, and the plant
// with the held pieces' mass (moved with a rigid-body chain; a feedforward drive ignores it).
cyber::plant::RunnerSetup runnerSetup(const cyber::config::Config& config, const SimOptions& options,
                                      const cyber::planner::JointVector& initial_q) {
  const auto& robot = config.robot;
  cyber::plant::RunnerSetup setup;
  setup.options = options;
  setup.options.initial_q = initial_q;
  for (int j = 0; j < robot.jointCount(); ++j) {
    setup.joint_devices.push_back(static_cast<std::uint8_t>(config.daemon.devices.joints[static_cast<size_t>(j)]));
    setup.joint_names.push_back(robot.joints[j].name);
    setup.joint_units.push_back(cyber::planner::unitName(robot.joints[j].type));
  }
  setup.state_channel = config.daemon.channels.state;
  setup.can_interface = options.can_interface.value_or(config.daemon.can_interface);
  auto& sim = setup.simulation;
  std::string piece_names;
  for (const std::string& piece : options.pieces) piece_names += (piece_names.empty() ? "" : ",") + piece;
  const auto named_set = robot.piecesNamed(piece_names);  // each name was checked above
  const cyber::planner::HeldPieces held = named_set ? named_set.value() : cyber::planner::HeldPieces{};
  sim = cyber::plant::SimulationSettings(cyber::plant::MechanismPlant::fromRobot(robot, held),
                                         options.controller_bandwidth_radps);
  for (int joint = 0; joint < robot.jointCount(); ++joint) {
    if (const auto& gains = options.joint_gains[static_cast<size_t>(joint)]) sim.gains[joint] = *gains;
  }
  sim.setpoint_timeout_s = options.setpoint_timeout_s;
  return setup;
}

// Only the joints' setpoint ids reach the simulator; the kernel drops everything else.
cyber::can::SocketOptions setpointSocketOptions(const cyber::plant::RunnerSetup& setup) {
  cyber::can::SocketOptions socket_options;
  std::vector<cyber::can::IdFilter> filters;
  for (const std::uint8_t device : setup.joint_devices) {
    filters.push_back(cyber::can::IdFilter::exact(
        cyber::can::teamFrameId(cyber::can::kSetpointApiClass, cyber::can::kSetpointApiIndex, device), true));
  }
  socket_options.filters = std::move(filters);
  return socket_options;
}

// The state log with its header (null without --log); false when it cannot be opened.
bool openStateLog(const SimOptions& options, const cyber::config::Config& config, std::FILE*& log) {
  log = nullptr;
  if (!options.log_path) return true;
  log = std::fopen(options.log_path->c_str(), "w");
  if (log == nullptr) {
    std::perror(("cyber-plant-sim: " + *options.log_path).c_str());
    return false;
  }
  std::setvbuf(log, nullptr, _IOFBF, 1 << 16);
  std::fprintf(log, "%s\n", cyber::plant::stateLogHeader(config.robot.joints).c_str());
  return true;
}

// SCHED_FIFO at --realtime's priority (none when 0); false when the kernel refuses.
bool applyRealtimePriority(const SimOptions& options) {
  if (options.realtime_priority <= 0) return true;
  sched_param param{};
  param.sched_priority = options.realtime_priority;
  if (sched_setscheduler(0, SCHED_FIFO, &param) != 0) {
    std::perror("cyber-plant-sim: --realtime: sched_setscheduler");
    return false;
  }
  return true;
}

// The control FIFO (-1 without --control), opened read-write: it then never reports end-of-file
// when a writer such as `echo KIND > FIFO` closes it. False when it cannot be made or opened.
bool openControlFifo(const SimOptions& options, int& control_fd) {
  control_fd = -1;
  if (!options.control_path) return true;
  const char* path = options.control_path->c_str();
  if (::mkfifo(path, 0600) != 0 && errno != EEXIST) {
    std::perror(("cyber-plant-sim: mkfifo " + *options.control_path).c_str());
    return false;
  }
  control_fd = ::open(path, O_RDWR | O_NONBLOCK | O_CLOEXEC);
  struct stat info {};
  if (control_fd < 0 || ::fstat(control_fd, &info) != 0 || !S_ISFIFO(info.st_mode)) {
    std::cerr << "cyber-plant-sim: --control " << *options.control_path << " is not a FIFO it can open\n";
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  // SIGINT/SIGTERM are taken through the event loop's signalfd; block them before any library
  // can start a thread that would otherwise receive them.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  const auto parsed = cyber::plant::parseSimArguments(std::vector<std::string>(argv + 1, argv + argc));
  const cyber::cli::ProgramUsage program{"cyber-plant-sim", std::string(cyber::plant::simUsage()), true};
  if (const auto status = cyber::cli::exitBeforeWork(parsed, program)) return *status;
  const SimOptions& options = parsed->options;

  cyber::config::Config config;
  try {
    config = options.config_path ? cyber::config::loadConfigFile(*options.config_path)
                                 : cyber::config::loadEmbeddedDefaultConfig();
  } catch (const std::exception& error) {
    std::cerr << "cyber-plant-sim: " << error.what() << "\n";
    return 2;
  }
  const cyber::planner::JointVector initial_q = options.initial_q.value_or(defaultInitialPose(config));
  if (const std::optional<int> status = refusedOptions(config, options, initial_q, program)) return *status;
  const cyber::plant::RunnerSetup setup = runnerSetup(config, options, initial_q);

  auto socket = cyber::can::CanSocket::open(setup.can_interface, setpointSocketOptions(setup));
  if (!socket) {
    std::cerr << "cyber-plant-sim: " << socket.error().message << "\n";
    return 1;
  }
  const std::string lcm_url = options.lcm_url.value_or(config.daemon.lcm_url);
  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    std::cerr << "cyber-plant-sim: cannot open LCM at " << lcm_url << "\n";
    return 1;
  }
  std::FILE* log = nullptr;
  if (!openStateLog(options, config, log)) return 1;
  if (!applyRealtimePriority(options)) return 1;
  int control_fd = -1;
  if (!openControlFifo(options, control_fd)) return 1;

  const int status = cyber::plant::runSimulator(setup, std::move(socket).value(), lcm, log, control_fd);
  if (control_fd >= 0) ::close(control_fd);
  if (log != nullptr && std::fclose(log) != 0) {
    std::perror("cyber-plant-sim: writing the log");
    return 1;
  }
  return status;
}
