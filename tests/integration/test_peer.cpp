// cyber-test-peer: the other side of cyber-plannerd for the integration tests (python3 here has
// no lcm module). One subcommand per job:
//   state   --at Q0,Q1,... [--rate HZ] [--seconds S]   publish ARM_STATE, following the ARM_SETPOINT echo
//   flood   --to Q0,Q1,... --to ... --count N [--rate HZ] [--first-id N]   publish exactly N goals, paced
//   garbage [--count N]                           undecodable bytes on ARM_GOAL and ARM_STATE
//   watch   --first-id N --count K [--timeout S] [--rcvbuf-bytes B]   wait until each id has one final
//           status; print tallies, what was seen of each id without one, and the kernel's drops on
//           this process's sockets. Exit 0, 1 (an answer missing or doubled), 3 (missing, but the
//           kernel dropped datagrams on the watcher's own socket: the run is void)
//   status  [--timeout S]                         print one ARM_DAEMON_STATUS as key=value lines
//   cancel  --id N --action hold|release          publish one ARM_CANCEL (-1: whatever goal is active)
// Every subcommand takes --lcm-url URL. Exit 0 on success, 1 otherwise, 2 for bad arguments.

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "cyber/cli/argument_parser.hpp"
#include "cyber/cli/number_text.hpp"
#include "cyber/config/daemon_settings.hpp"
#include "cyberplanner/arm_cancel_t.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"
#include "cyberplanner/arm_state_t.hpp"
#include "own_udp_sockets.hpp"

namespace {

using Clock = std::chrono::steady_clock;
volatile std::sig_atomic_t g_stop = 0;

struct Args {
  std::string command;
  std::string lcm_url = cyber::config::kDefaultLcmUrl;  // the daemon's default (docs/lcm.md)
  std::vector<std::vector<double>> targets;             // --to / --at: one value per joint, chain order
  double rate_hz = 100.0;
  double seconds = 1e9;
  long long first_id = 1;
  long long count = 100;
  double timeout_s = 10.0;
  int rcvbuf_bytes = 0;  // watch: forced receive buffer (0: LCM's choice)
  long long id = -1;     // cancel
  std::string action;    // cancel: hold | release
};

// A number option's handler: stores it when `parse` accepts it.
template <class T, class Parse>
cyber::cli::ValueHandler number(T* into, Parse parse) {
  return [into, parse](const std::string& text) -> std::string {
    const auto value = parse(text);
    if (!value) return "expects a number, got '" + text + "'";
    *into = static_cast<T>(*value);
    return "";
  };
}

bool parse(int argc, char** argv, Args& args) {
  if (argc < 2) return false;
  args.command = argv[1];
  const auto real = [](std::string_view t) { return cyber::cli::parseNumber(t); };
  const auto integer = [](std::string_view t) { return cyber::cli::parseInteger(t); };
  cyber::cli::ArgumentParser parser;
  parser.option("--lcm-url", [&](const std::string& value) {
    args.lcm_url = value;
    return std::string();
  });
  const cyber::cli::ValueHandler target = [&](const std::string& value) -> std::string {
    std::vector<double> values;
    for (size_t from = 0;;) {
      const size_t comma = value.find(',', from);
      const auto number = cyber::cli::parseNumber(std::string_view(value).substr(from, comma - from));
      if (!number) return "expects Q0,Q1,..., got '" + value + "'";
      values.push_back(*number);
      if (comma == std::string::npos) break;
      from = comma + 1;
    }
    args.targets.push_back(std::move(values));
    return "";
  };
  parser.option("--to", target);
  parser.option("--at", target);
  parser.option("--rate", number(&args.rate_hz, real));
  parser.option("--seconds", number(&args.seconds, real));
  parser.option("--timeout", number(&args.timeout_s, real));
  parser.option("--first-id", number(&args.first_id, integer));
  parser.option("--count", number(&args.count, integer));
  parser.option("--rcvbuf-bytes", number(&args.rcvbuf_bytes, integer));
  parser.option("--id", number(&args.id, integer));
  parser.option("--action", [&](const std::string& value) -> std::string {
    if (value != "hold" && value != "release") return "expects hold or release, got '" + value + "'";
    args.action = value;
    return "";
  });
  const auto scan = parser.parse(std::vector<std::string>(argv + 2, argv + argc));
  if (!scan) std::fprintf(stderr, "cyber-test-peer: %s\n", scan.error().message.c_str());
  return scan && scan.value() == cyber::cli::Scan::kComplete && args.rate_hz > 0.0;
}

std::int64_t nowMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// Paces a loop at rate_hz for `seconds` or `max_steps` steps, whichever ends first (or until
// SIGTERM); calls step(k) each period and lets LCM handle incoming messages in between.
template <class Step>
void paced(lcm::LCM& lcm, double rate_hz, double seconds, Step step, long long max_steps = -1) {
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate_hz));
  const auto end = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  auto next = Clock::now();
  for (long long k = 0; !g_stop && Clock::now() < end && (max_steps < 0 || k < max_steps); ++k) {
    step(k);
    next += period;
    while (lcm.handleTimeout(0) > 0) {
    }
    std::this_thread::sleep_until(next);
  }
}

struct Follower {
  std::vector<double> q;  // each joint as last commanded
  void onSetpoint(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_setpoint_t* m) {
    if (m->position.size() == q.size()) q = m->position;  // the daemon's joint count is --at's
  }
};

int runState(lcm::LCM& lcm, const Args& args) {
  if (args.targets.size() != 1) return 2;
  Follower follower{args.targets[0]};
  lcm.subscribe("ARM_SETPOINT", &Follower::onSetpoint, &follower);
  paced(lcm, args.rate_hz, args.seconds, [&](long long) {
    cyberplanner::arm_state_t state{};
    state.utime = nowMicros();
    state.num_joints = static_cast<std::int8_t>(follower.q.size());
    state.position = follower.q;
    state.velocity.assign(follower.q.size(), 0.0);
    lcm.publish("ARM_STATE", &state);
  });
  return 0;
}

int runFlood(lcm::LCM& lcm, const Args& args) {
  if (args.targets.empty()) return 2;
  long long sent = 0;
  paced(
      lcm, args.rate_hz, args.seconds,
      [&](long long k) {
        cyberplanner::arm_goal_t goal{};
        goal.utime = nowMicros();
        goal.request_id = args.first_id + k;
        const auto& target = args.targets[static_cast<size_t>(k) % args.targets.size()];
        goal.num_joints = static_cast<std::int8_t>(target.size());
        goal.position = target;
        lcm.publish("ARM_GOAL", &goal);
        ++sent;
      },
      args.count);
  std::printf("sent %lld goals, ids %lld..%lld\n", sent, args.first_id, args.first_id + sent - 1);
  return 0;
}

int runGarbage(lcm::LCM& lcm, const Args& args) {
  std::mt19937 random(12345);
  std::uniform_int_distribution<int> byte(0, 255), length(1, 200);
  for (long long i = 0; i < args.count; ++i) {
    std::vector<std::uint8_t> bytes(static_cast<size_t>(length(random)));
    for (auto& b : bytes) b = static_cast<std::uint8_t>(byte(random));
    const char* channel = i % 2 == 0 ? "ARM_GOAL" : "ARM_STATE";
    lcm.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
    // Paced (2000/s), so what is measured is the daemon, not UDP dropping a burst.
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  // A message of another type on each channel, and a goal whose string length field is huge.
  cyberplanner::arm_state_t state{};
  lcm.publish("ARM_GOAL", &state);
  cyberplanner::arm_goal_t goal{};
  lcm.publish("ARM_STATE", &goal);
  goal.scene_name = "reef";
  std::vector<std::uint8_t> bytes(static_cast<size_t>(goal.getEncodedSize()));
  goal.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  const size_t length_at = bytes.size() - 4 - 5;
  bytes[length_at] = 0x7f;
  bytes[length_at + 1] = bytes[length_at + 2] = bytes[length_at + 3] = 0xff;
  lcm.publish("ARM_GOAL", bytes.data(), static_cast<unsigned>(bytes.size()));
  std::printf("sent %lld garbage messages\n", args.count + 3);
  return 0;
}

struct Tally {
  long long first = 0, count = 0;
  std::map<long long, int> finals;  // id -> number of final statuses
  std::map<int, long long> by_status;
  std::map<long long, unsigned> seen;  // id -> bit per status value received
  void onStatus(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_plan_status_t* m) {
    if (m->request_id < first || m->request_id >= first + count) return;
    if (m->status >= 0 && m->status < 32) seen[m->request_id] |= 1u << m->status;
    if (m->status >= cyberplanner::arm_plan_status_t::STATUS_DONE) {
      ++finals[m->request_id];
      ++by_status[m->status];
    }
  }
};

// "accepted planning", or "none": the statuses in `bits` (a Tally::seen entry), in wire order.
std::string statusNames(unsigned bits) {
  static const char* const kNames[] = {"accepted", "planning", "executing", "done", "rejected", "failed", "cancelled"};
  std::string out;
  for (unsigned s = 0; s < sizeof(kNames) / sizeof(kNames[0]); ++s) {
    if ((bits & (1u << s)) == 0) continue;
    if (!out.empty()) out += ' ';
    out += kNames[s];
  }
  return out.empty() ? "none" : out;
}

int runWatch(lcm::LCM& lcm, const Args& args) {
  Tally tally;
  tally.first = args.first_id;
  tally.count = args.count;
  // Unbounded: LCM's default of 30 queued messages per subscription drops statuses in the flood
  // whenever this process is descheduled for a few milliseconds.
  lcm.subscribe("ARM_PLAN_STATUS", &Tally::onStatus, &tally)->setQueueCapacity(0);
  // LCM has opened its sockets by now (subscribing sets up the receive side).
  const auto sockets = cyber::test::ownUdpSockets();
  if (sockets.empty()) {
    std::fprintf(stderr, "cyber-test-peer: no UDP socket of its own in /proc/self/net/udp\n");
    return 1;
  }
  if (args.rcvbuf_bytes > 0) {
    const long long got = cyber::test::forceReceiveBuffer(sockets, args.rcvbuf_bytes);
    if (got < args.rcvbuf_bytes) {
      std::fprintf(stderr, "cyber-test-peer: cannot force a %d-byte receive buffer (SO_RCVBUF %lld; root needed)\n",
                   args.rcvbuf_bytes, got);
      return 1;
    }
  }
  const std::int64_t drops_before = cyber::test::kernelDrops(sockets);
  // Subscribed: a sender may start now (statuses sent before this socket joined are not seen).
  std::printf("watching ids %lld..%lld\n", args.first_id, args.first_id + args.count - 1);
  std::fflush(stdout);
  const auto end =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(args.timeout_s));
  while (Clock::now() < end && static_cast<long long>(tally.finals.size()) < args.count) lcm.handleTimeout(50);
  // A little longer, to catch a second final status for any id.
  const auto settle = Clock::now() + std::chrono::milliseconds(300);
  while (Clock::now() < settle) lcm.handleTimeout(50);
  long long duplicates = 0;
  for (const auto& [id, n] : tally.finals) duplicates += n > 1 ? 1 : 0;
  int listed = 0;
  for (long long id = tally.first; id < tally.first + tally.count && listed < 20; ++id) {
    if (tally.finals.count(id) == 0) {
      std::printf("no final status for request %lld (seen: %s)\n", id, statusNames(tally.seen[id]).c_str());
      ++listed;
    }
  }
  std::printf(
      "final statuses for %zu of %lld ids; duplicates %lld; done %lld rejected %lld failed %lld cancelled %lld\n",
      tally.finals.size(), args.count, duplicates, tally.by_status[3], tally.by_status[4], tally.by_status[5],
      tally.by_status[6]);
  const std::int64_t drops = cyber::test::kernelDrops(sockets) - drops_before;
  std::printf("watcher: %zu UDP sockets, kernel drops on them during the watch %lld\n", sockets.size(),
              static_cast<long long>(drops));
  if (duplicates != 0) return 1;
  if (static_cast<long long>(tally.finals.size()) == args.count) return 0;
  return drops > 0 ? 3 : 1;
}

int runCancel(lcm::LCM& lcm, const Args& args) {
  if (args.action.empty()) return 2;
  cyberplanner::arm_cancel_t cancel{};
  cancel.utime = nowMicros();
  cancel.request_id = args.id;
  cancel.action =
      args.action == "hold" ? cyberplanner::arm_cancel_t::ACTION_HOLD : cyberplanner::arm_cancel_t::ACTION_RELEASE;
  if (lcm.publish("ARM_CANCEL", &cancel) != 0) return 1;
  std::printf("sent ARM_CANCEL %s for request %lld\n", args.action.c_str(), args.id);
  return 0;
}

struct StatusCatcher {
  bool got = false;
  cyberplanner::arm_daemon_status_t status{};
  void on(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_daemon_status_t* m) {
    status = *m;
    got = true;
  }
};

int runStatus(lcm::LCM& lcm, const Args& args) {
  StatusCatcher catcher;
  lcm.subscribe("ARM_DAEMON_STATUS", &StatusCatcher::on, &catcher);
  const auto end =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(args.timeout_s));
  while (!catcher.got && Clock::now() < end) lcm.handleTimeout(50);
  if (!catcher.got) return 1;
  const auto& s = catcher.status;
  std::printf("utime=%lld\nnum_joints=%d\n", static_cast<long long>(s.utime), s.num_joints);
  std::string names;
  for (const std::string& name : s.joint_names) names.append(names.empty() ? "" : ",").append(name);
  std::printf("joint_names=%s\n", names.c_str());
  std::printf(
      "mode=%d\nrobot_enabled=%d\nmotion_allowed=%d\nactive_request_id=%lld\nstate_age_ms=%.1f\n"
      "goals_received=%lld\nplans_succeeded=%lld\nplans_failed=%lld\nframes_sent=%lld\ncan_errors=%lld\n"
      "decode_errors=%lld\nstream_overruns=%lld\npublish_failures=%lld\nplan_time_p50_ms=%.2f\nplan_time_p99_ms=%.2f\n"
      "stream_jitter_p50_us=%.1f\nstream_jitter_p99_us=%.1f\nstream_jitter_max_us=%.1f\nrealtime_priority=%d\n",
      s.mode, s.robot_enabled, s.motion_allowed, static_cast<long long>(s.active_request_id), s.state_age_ms,
      static_cast<long long>(s.goals_received), static_cast<long long>(s.plans_succeeded),
      static_cast<long long>(s.plans_failed), static_cast<long long>(s.frames_sent),
      static_cast<long long>(s.can_errors), static_cast<long long>(s.decode_errors),
      static_cast<long long>(s.stream_overruns), static_cast<long long>(s.publish_failures), s.plan_time_p50_ms,
      s.plan_time_p99_ms, s.stream_jitter_p50_us, s.stream_jitter_p99_us, s.stream_jitter_max_us, s.realtime_priority);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  if (!parse(argc, argv, args)) {
    std::fprintf(stderr,
                 "usage: cyber-test-peer state|flood|garbage|watch|status|cancel [options] (see test_peer.cpp)\n");
    return 2;
  }
  std::signal(SIGTERM, [](int) { g_stop = 1; });
  std::signal(SIGINT, [](int) { g_stop = 1; });
  lcm::LCM lcm(args.lcm_url);
  if (!lcm.good()) {
    std::fprintf(stderr, "cyber-test-peer: cannot open LCM\n");
    return 1;
  }
  int rc = 2;
  if (args.command == "state")
    rc = runState(lcm, args);
  else if (args.command == "flood")
    rc = runFlood(lcm, args);
  else if (args.command == "garbage")
    rc = runGarbage(lcm, args);
  else if (args.command == "watch")
    rc = runWatch(lcm, args);
  else if (args.command == "status")
    rc = runStatus(lcm, args);
  else if (args.command == "cancel")
    rc = runCancel(lcm, args);
  if (rc == 2) std::fprintf(stderr, "cyber-test-peer: bad arguments for '%s'\n", args.command.c_str());
  return rc;
}
