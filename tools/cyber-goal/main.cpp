// cyber-goal: publish one ARM_GOAL and wait for its final ARM_PLAN_STATUS (goalUsage()).

#include <lcm/lcm-cpp.hpp>

#include <array>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

#include "cyber/cli/usage_exit.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"
#include "goal_arguments.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using Status = cyberplanner::arm_plan_status_t;

const char* statusName(int status) {
  switch (status) {
    case Status::STATUS_ACCEPTED: return "accepted";
    case Status::STATUS_PLANNING: return "planning";
    case Status::STATUS_EXECUTING: return "executing";
    case Status::STATUS_DONE: return "done";
    case Status::STATUS_REJECTED: return "rejected";
    case Status::STATUS_FAILED: return "failed";
    case Status::STATUS_CANCELLED: return "cancelled";
    default: return "unknown";
  }
}

struct Watcher {
  std::int64_t request_id = 0;
  bool daemon_heard = false;
  int final_status = -1;

  void onDaemonStatus(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_daemon_status_t*) {
    daemon_heard = true;
  }
  void onStatus(const lcm::ReceiveBuffer*, const std::string&, const Status* m) {
    if (m->request_id != request_id || final_status >= 0) return;
    std::printf("request %lld %s", static_cast<long long>(m->request_id), statusName(m->status));
    if (m->status == Status::STATUS_EXECUTING) {
      std::printf(" (duration %.3f s, planned in %.1f ms)", m->duration_s, m->total_ms);
    }
    if (!m->reason.empty()) std::printf(": %s", m->reason.c_str());
    std::printf("\n");
    std::fflush(stdout);
    if (m->status >= Status::STATUS_DONE) final_status = m->status;
  }
  void onTrajectory(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_trajectory_t* m) {
    if (m->request_id != request_id) return;
    std::printf("request %lld trajectory: %d samples, dt %.4f s, duration %.3f s\n",
                static_cast<long long>(m->request_id), m->num_samples, m->dt_s, m->duration_s);
    std::fflush(stdout);
  }
};

// Handles messages until `done()` or the deadline; false on timeout.
template <class Done>
bool handleUntil(lcm::LCM& lcm, Clock::time_point deadline, Done done) {
  while (!done()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    if (lcm.handleTimeout(static_cast<int>(std::min<long long>(left, 100))) < 0) return false;
  }
  return true;
}

// --to as --config sees it (which, when given, must load either way): a pose name the config does
// not give the held set is refused here, before anything is sent.
cyber::Result<std::vector<double>, cyber::cli::ArgumentStatus> target(const cyber::tools::GoalArguments& args) {
  if (args.config_path.empty()) return args.position;
  cyber::config::Config config;
  try {
    config = cyber::config::loadConfigFile(args.config_path);
  } catch (const cyber::config::ConfigError& e) {
    return cyber::cli::badUsage(e.what());
  }
  return cyber::tools::goalPosition(args, config);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cyber::tools;
  const auto parsed = parseGoalArguments(std::vector<std::string>(argv + 1, argv + argc));
  if (const auto status = cyber::cli::exitBeforeWork(parsed, {"cyber-goal", goalUsage(), true})) return *status;
  const GoalArguments& args = parsed.value();
  const auto position = target(args);
  if (!position) {
    std::cerr << "cyber-goal: " << position.error().message << "\n";
    return kExitUsage;
  }

  lcm::LCM lcm(args.lcm_url);
  if (!lcm.good()) {
    std::cerr << "cyber-goal: cannot open LCM" << (args.lcm_url.empty() ? "" : " at '" + args.lcm_url + "'") << "\n";
    return kExitLcm;
  }
  Watcher watcher;
  watcher.request_id =
      args.request_id >= 0
          ? args.request_id
          : std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
                    .count() %
                1'000'000'000;
  lcm.subscribe("ARM_DAEMON_STATUS", &Watcher::onDaemonStatus, &watcher);
  lcm.subscribe("ARM_PLAN_STATUS", &Watcher::onStatus, &watcher);
  lcm.subscribe("ARM_TRAJECTORY", &Watcher::onTrajectory, &watcher);

  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(args.timeout_s));
  if (args.wait_for_daemon && !handleUntil(lcm, deadline, [&] { return watcher.daemon_heard; })) {
    std::cerr << "cyber-goal: no cyber-plannerd heard on ARM_DAEMON_STATUS within " << args.timeout_s << " s\n";
    return kExitTimeout;
  }

  cyberplanner::arm_goal_t goal{};
  goal.utime =
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count();
  goal.request_id = watcher.request_id;
  // A name goes as the name: the daemon resolves it with its own configuration (docs/lcm.md,
  // "Named goals"), and then needs no joint values.
  goal.pose_name = args.pose_name;
  if (args.pose_name.empty()) goal.position = args.position;
  goal.num_joints = static_cast<std::int8_t>(goal.position.size());
  goal.pieces = args.pieces;
  goal.num_pieces = static_cast<std::int8_t>(goal.pieces.size());
  goal.scene_name = args.scene;
  goal.scene_offset_m = args.scene_offset_m;
  lcm.publish("ARM_GOAL", &goal);

  if (!handleUntil(lcm, deadline, [&] { return watcher.final_status >= 0; })) {
    std::cerr << "cyber-goal: no final status for request " << watcher.request_id << " within " << args.timeout_s
              << " s\n";
    return kExitTimeout;
  }
  switch (watcher.final_status) {
    case Status::STATUS_DONE: return kExitDone;
    case Status::STATUS_REJECTED: return kExitRejected;
    case Status::STATUS_FAILED: return kExitFailed;
    default: return kExitCancelled;
  }
}
