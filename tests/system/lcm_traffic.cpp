// Test helper for the system tests: puts the project's six LCM types on the wire, or counts what
// arrives on their channels.
//
//   lcm_traffic publish --lcm-url URL --rate-hz R --duration-s D
//       publishes one message of each type on its channel (design.md) R times a second for D s
//   lcm_traffic listen --lcm-url URL --duration-s D [--quiet-s Q]
//       prints "listening" once subscribed, then "CHANNEL received decoded" for each of the six channels after D s;
//       "decoded" counts messages that decode as the channel's type with the values publish puts in. With --quiet-s it
//       stops earlier: Q s after the last message, once one has arrived.
//
// Exit codes: 0 done, 2 bad arguments, 1 LCM could not be opened.

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>
#include <thread>

#include "cyber/lcmtypes/safe_decode.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"
#include "cyberplanner/arm_state_t.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// A recognisable value in every message, so "decoded" means the payload survived.
constexpr std::int64_t kRequestId = 4242;
constexpr double kElevatorM = 0.625;

cyberplanner::arm_goal_t goal(std::int64_t utime) {
  cyberplanner::arm_goal_t m{};
  m.utime = utime;
  m.request_id = kRequestId;
  m.num_joints = 2;
  m.position = {kElevatorM, 1.25};
  m.num_pieces = 1;
  m.pieces = {"coral"};
  m.scene_name = "reef";
  m.scene_offset_m = 0.125;
  return m;
}

cyberplanner::arm_state_t state(std::int64_t utime) {
  cyberplanner::arm_state_t m{};
  m.utime = utime;
  m.num_joints = 2;
  m.position = {kElevatorM, 0.5};
  m.velocity = {0.0, 0.0};
  return m;
}

cyberplanner::arm_plan_status_t planStatus(std::int64_t utime) {
  cyberplanner::arm_plan_status_t m{};
  m.utime = utime;
  m.request_id = kRequestId;
  m.status = cyberplanner::arm_plan_status_t::STATUS_EXECUTING;
  m.reason = "";
  m.total_ms = 12.5;
  m.duration_s = 0.8;
  return m;
}

cyberplanner::arm_trajectory_t trajectory(std::int64_t utime) {
  cyberplanner::arm_trajectory_t m{};
  m.utime = utime;
  m.request_id = kRequestId;
  m.start_utime = utime;
  m.duration_s = 0.8;
  m.dt_s = 0.1;
  m.num_samples = 9;
  m.num_joints = 2;
  for (auto* table : {&m.position, &m.velocity, &m.volts}) table->resize(2);  // [joint][sample]
  for (int k = 0; k < m.num_samples; ++k) {
    const double t = k * m.dt_s;
    m.t_s.push_back(t);
    m.position[0].push_back(kElevatorM * t / m.duration_s);
    m.position[1].push_back(1.25 * t / m.duration_s);
    m.velocity[0].push_back(kElevatorM / m.duration_s);
    m.velocity[1].push_back(1.25 / m.duration_s);
    m.volts[0].push_back(1.5);
    m.volts[1].push_back(0.5);
  }
  return m;
}

cyberplanner::arm_setpoint_t setpoint(std::int64_t utime) {
  cyberplanner::arm_setpoint_t m{};
  m.utime = utime;
  m.mode = cyberplanner::arm_setpoint_t::MODE_MOVING;
  m.request_id = kRequestId;
  m.num_joints = 2;
  m.position = {kElevatorM, 0.75};
  m.velocity = {0.0, 0.0};
  m.volts = {0.0, 0.0};
  m.sequence = {0, 0};
  return m;
}

cyberplanner::arm_daemon_status_t daemonStatus(std::int64_t utime) {
  cyberplanner::arm_daemon_status_t m{};
  m.utime = utime;
  m.mode = cyberplanner::arm_daemon_status_t::MODE_MOVING;
  m.active_request_id = kRequestId;
  m.goals_received = 1;
  m.num_joints = 2;
  m.joint_names = {"elevator", "arm"};
  m.joint_units = {"m", "rad"};
  return m;
}

// Each channel's check that a decoded message is the one publish sent.
bool isOurs(const cyberplanner::arm_goal_t& m) {
  return m.request_id == kRequestId && m.scene_name == "reef" && m.pieces == std::vector<std::string>{"coral"} &&
         m.scene_offset_m == 0.125;
}
bool isOurs(const cyberplanner::arm_state_t& m) { return m.num_joints == 2 && m.position[0] == kElevatorM; }
bool isOurs(const cyberplanner::arm_plan_status_t& m) { return m.request_id == kRequestId; }
bool isOurs(const cyberplanner::arm_trajectory_t& m) {
  return m.request_id == kRequestId && m.num_samples == 9 && m.num_joints == 2 && m.position[0].back() == kElevatorM;
}
bool isOurs(const cyberplanner::arm_setpoint_t& m) { return m.request_id == kRequestId; }
bool isOurs(const cyberplanner::arm_daemon_status_t& m) {
  return m.active_request_id == kRequestId && m.num_joints == 2 && m.joint_names[1] == "arm" && m.joint_units[0] == "m";
}

struct Counts {
  long received = 0;
  long decoded = 0;
};

class Listener {
 public:
  explicit Listener(lcm::LCM& lcm) {
    watch<cyberplanner::arm_goal_t>(lcm, "ARM_GOAL");
    watch<cyberplanner::arm_state_t>(lcm, "ARM_STATE");
    watch<cyberplanner::arm_plan_status_t>(lcm, "ARM_PLAN_STATUS");
    watch<cyberplanner::arm_trajectory_t>(lcm, "ARM_TRAJECTORY");
    watch<cyberplanner::arm_setpoint_t>(lcm, "ARM_SETPOINT");
    watch<cyberplanner::arm_daemon_status_t>(lcm, "ARM_DAEMON_STATUS");
  }
  long total() const {
    long sum = 0;
    for (const auto& entry : counts_) sum += entry.second.received;
    return sum;
  }
  void print() const {
    for (const auto& [channel, counts] : counts_) {
      std::printf("%s %ld %ld\n", channel.c_str(), counts.received, counts.decoded);
    }
  }

 private:
  template <class Message>
  void watch(lcm::LCM& lcm, const std::string& channel) {
    counts_[channel];
    lcm.subscribeFunction(channel, &Listener::onMessage<Message>, this);
  }
  template <class Message>
  static void onMessage(const lcm::ReceiveBuffer* rbuf, const std::string& channel, Listener* self) {
    Counts& counts = self->counts_[channel];
    ++counts.received;
    Message message{};
    if (cyber::lcmtypes::safeDecode(message, rbuf->data, static_cast<int>(rbuf->data_size)) >= 0 && isOurs(message)) {
      ++counts.decoded;
    }
  }
  std::map<std::string, Counts> counts_;
};

std::int64_t nowUtime() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

int publish(lcm::LCM& lcm, double rate_hz, double duration_s) {
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate_hz));
  const auto end =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(duration_s));
  auto next = Clock::now();
  long rounds = 0;
  while (next < end) {
    const std::int64_t utime = nowUtime();
    const auto goal_message = goal(utime);
    const auto state_message = state(utime);
    const auto plan_status_message = planStatus(utime);
    const auto trajectory_message = trajectory(utime);
    const auto setpoint_message = setpoint(utime);
    const auto daemon_status_message = daemonStatus(utime);
    int failures = 0;
    failures += lcm.publish("ARM_GOAL", &goal_message) != 0;
    failures += lcm.publish("ARM_STATE", &state_message) != 0;
    failures += lcm.publish("ARM_PLAN_STATUS", &plan_status_message) != 0;
    failures += lcm.publish("ARM_TRAJECTORY", &trajectory_message) != 0;
    failures += lcm.publish("ARM_SETPOINT", &setpoint_message) != 0;
    failures += lcm.publish("ARM_DAEMON_STATUS", &daemon_status_message) != 0;
    if (failures != 0) {
      std::fprintf(stderr, "lcm_traffic: %d publish calls failed\n", failures);
      return 1;
    }
    ++rounds;
    next += period;
    std::this_thread::sleep_until(next);
  }
  std::printf("published %ld rounds of 6 messages\n", rounds);
  return 0;
}

int listen(lcm::LCM& lcm, double duration_s, double quiet_s) {
  Listener listener(lcm);
  // Tests wait for this line before they start sending.
  std::printf("listening\n");
  std::fflush(stdout);
  const auto end =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(duration_s));
  const auto quiet = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(quiet_s));
  auto last_message = Clock::now();
  for (auto now = Clock::now(); now < end; now = Clock::now()) {
    if (quiet_s > 0.0 && listener.total() > 0 && now - last_message >= quiet) break;
    const auto left_ms = std::chrono::duration_cast<std::chrono::milliseconds>(end - now).count();
    const int handled = lcm.handleTimeout(static_cast<int>(std::min<long long>(left_ms + 1, 100)));
    if (handled < 0) {
      std::fprintf(stderr, "lcm_traffic: LCM receive failed\n");
      return 1;
    }
    if (handled > 0) last_message = Clock::now();
  }
  listener.print();
  return 0;
}

int usage() {
  std::fprintf(stderr,
               "usage: lcm_traffic publish --lcm-url URL --rate-hz R --duration-s D\n"
               "       lcm_traffic listen --lcm-url URL --duration-s D [--quiet-s Q]\n");
  return 2;
}

bool parsePositive(const char* text, double& value) {
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && value > 0.0 && value < 1e6;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string_view mode = argv[1];
  std::string url;
  double rate_hz = 5.0;
  double duration_s = 0.0;
  double quiet_s = 0.0;
  for (int i = 2; i < argc; i += 2) {
    if (i + 1 == argc) return usage();  // an option without its value
    const std::string_view key = argv[i];
    if (key == "--lcm-url") {
      url = argv[i + 1];
    } else if (key == "--rate-hz") {
      if (!parsePositive(argv[i + 1], rate_hz)) return usage();
    } else if (key == "--quiet-s") {
      if (!parsePositive(argv[i + 1], quiet_s)) return usage();
    } else if (key == "--duration-s") {
      if (!parsePositive(argv[i + 1], duration_s)) return usage();
    } else {
      return usage();
    }
  }
  if (url.empty() || duration_s <= 0.0 || (mode != "publish" && mode != "listen")) return usage();

  lcm::LCM lcm(url);
  if (!lcm.good()) {
    std::fprintf(stderr, "lcm_traffic: cannot open LCM at %s\n", url.c_str());
    return 1;
  }
  return mode == "publish" ? publish(lcm, rate_hz, duration_s) : listen(lcm, duration_s, quiet_s);
}
