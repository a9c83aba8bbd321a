// cyber-soak-peer: the robot side of a long run against a real cyber-plannerd (tools/soak,
// docs/testing.md "Soak"). One thread, paced at the state rate:
//   - ARM_STATE at 100 Hz, following the ARM_SETPOINT echo (the plant tracks perfectly);
//   - goals at random intervals: public poses (some sent while the previous one moves), infeasible
//     ones (out of range, in collision, unknown scene, not finite), malformed bytes on ARM_GOAL and
//     ARM_STATE, and now and then a burst of goals within a few milliseconds;
//   - every decodable goal must get exactly one final ARM_PLAN_STATUS (a lost or doubled answer
//     fails the run);
//   - every sample period: the daemon's RSS, open fds and threads from /proc/PID, and every counter
//     of the latest ARM_DAEMON_STATUS, one CSV row each.
// After the warm-up, RSS and fds must stay flat: the median of the last tenth of the samples may
// exceed the median of the first tenth by at most --rss-slack-kib, and fds and threads may not
// exceed their warm-up values.
//   cyber-soak-peer --daemon-pid PID --seconds S [--warmup S] [--sample-s S] [--csv FILE]
//                   [--seed N] [--lcm-url URL] [--rss-slack-kib K]
// Prints a summary as key=value lines; exit 0 when every check passed, 1 otherwise, 2 bad usage.

#include <dirent.h>

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "cyber/config/daemon_settings.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"
#include "cyberplanner/arm_state_t.hpp"
#include "public_moves.hpp"

namespace {

using Clock = std::chrono::steady_clock;
volatile std::sig_atomic_t g_stop = 0;

struct Args {
  long daemon_pid = 0;
  double seconds = 120.0;
  std::optional<double> warmup_s;
  double sample_s = 1.0;
  std::string csv_path;
  unsigned seed = 1;
  std::string lcm_url = cyber::config::kDefaultLcmUrl;  // the daemon's default (docs/lcm.md)
  long rss_slack_kib = 2048;
  double answer_timeout_s = 30.0;
};

std::optional<Args> parse(int argc, char** argv) {
  Args args;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string arg = argv[i], value = argv[i + 1];
    if (arg == "--daemon-pid")
      args.daemon_pid = std::atol(value.c_str());
    else if (arg == "--seconds")
      args.seconds = std::atof(value.c_str());
    else if (arg == "--warmup")
      args.warmup_s = std::atof(value.c_str());
    else if (arg == "--sample-s")
      args.sample_s = std::atof(value.c_str());
    else if (arg == "--csv")
      args.csv_path = value;
    else if (arg == "--seed")
      args.seed = static_cast<unsigned>(std::atol(value.c_str()));
    else if (arg == "--lcm-url")
      args.lcm_url = value;
    else if (arg == "--rss-slack-kib")
      args.rss_slack_kib = std::atol(value.c_str());
    else
      return std::nullopt;
  }
  if (argc % 2 == 0 || args.daemon_pid <= 0 || !(args.seconds > 0.0) || !(args.sample_s > 0.0)) return std::nullopt;
  return args;
}

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::int64_t wallMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// ---- the daemon process, from /proc ----

struct ProcessSample {
  long rss_kib = -1;
  long threads = -1;
  long fds = -1;
};

std::optional<ProcessSample> sampleProcess(long pid) {
  const std::string dir = "/proc/" + std::to_string(pid);
  std::ifstream status(dir + "/status");
  if (!status) return std::nullopt;
  ProcessSample sample;
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) sample.rss_kib = std::atol(line.c_str() + 6);
    if (line.rfind("Threads:", 0) == 0) sample.threads = std::atol(line.c_str() + 8);
    // A zombie or a process that is exiting has no VmRSS line: that is a crash for this run.
  }
  if (DIR* fd_dir = opendir((dir + "/fd").c_str())) {
    sample.fds = 0;
    while (const dirent* entry = readdir(fd_dir)) sample.fds += entry->d_name[0] != '.' ? 1 : 0;
    closedir(fd_dir);
  }
  if (sample.rss_kib < 0 || sample.fds < 0) return std::nullopt;
  return sample;
}

// ---- LCM side ----

struct Peer {
  double q0 = 0.20, q1 = 1.57;  // joint 0, joint 1: STOW until the first setpoint echo
  std::optional<cyberplanner::arm_daemon_status_t> status;
  Clock::time_point status_at{};
  long long status_messages = 0;
  std::map<std::int64_t, Clock::time_point> open_goals;  // sent, no final status yet
  std::map<std::int64_t, int> finals;                    // id -> final statuses seen (sent ids only)
  std::map<int, long long> by_status;
  long long foreign_finals = 0;  // finals for ids this run never sent

  void onSetpoint(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_setpoint_t* m) {
    if (m->num_joints != 2) return;  // the reference robot's elevator and arm (docs/lcm.md, "Joints by index")
    q0 = m->position[0];
    q1 = m->position[1];
  }
  void onDaemonStatus(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_daemon_status_t* m) {
    status = *m;
    status_at = Clock::now();
    ++status_messages;
  }
  void onPlanStatus(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_plan_status_t* m) {
    if (m->status < cyberplanner::arm_plan_status_t::STATUS_DONE) return;
    auto seen = finals.find(m->request_id);
    if (seen == finals.end()) {
      ++foreign_finals;
      return;
    }
    ++seen->second;
    ++by_status[m->status];
    open_goals.erase(m->request_id);
  }
};

// The measured state: wherever the daemon last commanded (a plant that tracks perfectly).
bool publishState(lcm::LCM& lcm, const Peer& peer) {
  cyberplanner::arm_state_t state{};
  state.utime = wallMicros();
  state.num_joints = 2;
  state.position = {peer.q0, peer.q1};
  state.velocity = {0.0, 0.0};
  return lcm.publish("ARM_STATE", &state) == 0;
}

// What the goal generator sends; the mix is documented in docs/testing.md ("Soak").
enum class GoalKind { kPose, kMidMotion, kOutOfRange, kCollision, kUnknownScene, kNotFinite, kMalformed, kBurst };

GoalKind pickKind(std::mt19937& random) {
  // Weights: mostly feasible moves, a fifth infeasible, a few malformed, rare bursts.
  static const std::vector<std::pair<GoalKind, int>> kWeights = {
      {GoalKind::kPose, 40},        {GoalKind::kMidMotion, 25}, {GoalKind::kOutOfRange, 5}, {GoalKind::kCollision, 5},
      {GoalKind::kUnknownScene, 4}, {GoalKind::kNotFinite, 4},  {GoalKind::kMalformed, 12}, {GoalKind::kBurst, 5}};
  int total = 0;
  for (const auto& [kind, weight] : kWeights) total += weight;
  int pick = std::uniform_int_distribution<int>(0, total - 1)(random);
  for (const auto& [kind, weight] : kWeights) {
    if (pick < weight) return kind;
    pick -= weight;
  }
  return GoalKind::kPose;
}

class GoalSender {
 public:
  GoalSender(lcm::LCM& lcm, Peer& peer, std::mt19937& random) : lcm_(lcm), peer_(peer), random_(random) {}

  // Sends what `kind` stands for; returns the delay until the next goal.
  double send(GoalKind kind) {
    const auto& poses = cyber::test::publicPoses("none");
    const auto& pose = poses[std::uniform_int_distribution<size_t>(0, poses.size() - 1)(random_)];
    cyberplanner::arm_goal_t goal{};
    goal.num_joints = 2;
    goal.position = {pose.q[0], pose.q[1]};
    switch (kind) {
      case GoalKind::kPose: publish(goal); return uniform(1.0, 4.0);
      case GoalKind::kMidMotion: publish(goal); return uniform(0.1, 0.6);  // the next one lands mid-motion
      case GoalKind::kOutOfRange:
        goal.position[0] = 5.0;
        publish(goal);
        return uniform(0.2, 1.0);
      case GoalKind::kCollision:
        goal.position[0] = 0.0;
        goal.position[1] = 4.71;
        publish(goal);
        return uniform(0.2, 1.0);
      case GoalKind::kUnknownScene:
        goal.scene_name = "moon";
        publish(goal);
        return uniform(0.2, 1.0);
      case GoalKind::kNotFinite:
        goal.position[1] = std::numeric_limits<double>::quiet_NaN();
        publish(goal);
        return uniform(0.2, 1.0);
      case GoalKind::kMalformed: malformed(goal); return uniform(0.1, 1.0);
      case GoalKind::kBurst: {
        const int count = std::uniform_int_distribution<int>(10, 40)(random_);
        for (int i = 0; i < count; ++i) {
          const auto& p = poses[static_cast<size_t>(i) % poses.size()];
          goal.position[0] = p.q[0];
          goal.position[1] = p.q[1];
          publish(goal);
        }
        ++bursts;
        return uniform(1.0, 3.0);
      }
    }
    return 1.0;
  }

  long long sent = 0, malformed_sent = 0, bursts = 0, publish_failures = 0;
  std::int64_t next_id = 1'000'000;

 private:
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random_); }

  void publish(cyberplanner::arm_goal_t& goal) {
    goal.utime = wallMicros();
    goal.request_id = next_id++;
    if (lcm_.publish("ARM_GOAL", &goal) != 0) {
      ++publish_failures;
      return;
    }
    peer_.open_goals[goal.request_id] = Clock::now();
    peer_.finals[goal.request_id] = 0;
    ++sent;
  }

  // Bytes the daemon must count and drop: random, a truncated goal, or a goal with a corrupt
  // string length; on ARM_GOAL or ARM_STATE.
  void malformed(cyberplanner::arm_goal_t& goal) {
    goal.request_id = -1;
    goal.scene_name = "reef";
    std::vector<std::uint8_t> bytes(static_cast<size_t>(goal.getEncodedSize()));
    goal.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    switch (std::uniform_int_distribution<int>(0, 2)(random_)) {
      case 0:
        bytes.resize(static_cast<size_t>(std::uniform_int_distribution<int>(1, 300)(random_)));
        for (auto& b : bytes) b = static_cast<std::uint8_t>(random_());
        break;
      case 1:
        bytes.resize(static_cast<size_t>(std::uniform_int_distribution<size_t>(0, bytes.size() - 1)(random_)));
        break;
      default: bytes[bytes.size() - 9] = 0x7f; break;  // the scene_name length's high byte
    }
    const char* channel = random_() % 2 == 0 ? "ARM_GOAL" : "ARM_STATE";
    if (lcm_.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size())) != 0) ++publish_failures;
    ++malformed_sent;
  }

  lcm::LCM& lcm_;
  Peer& peer_;
  std::mt19937& random_;
};

struct Row {
  double t_s = 0;
  ProcessSample process;
  cyberplanner::arm_daemon_status_t status{};
};

long median(std::vector<long> values) {
  if (values.empty()) return -1;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

void writeCsvHeader(std::FILE* csv) {
  std::fprintf(csv,
               "t_s,rss_kib,fds,threads,mode,goals_received,plans_succeeded,plans_failed,frames_sent,can_errors,"
               "decode_errors,stream_overruns,publish_failures,plan_time_p99_ms,stream_jitter_p99_us,"
               "stream_jitter_max_us,state_age_ms\n");
}

void writeCsvRow(std::FILE* csv, const Row& r) {
  const auto& s = r.status;
  std::fprintf(csv, "%.1f,%ld,%ld,%ld,%d,%lld,%lld,%lld,%lld,%lld,%lld,%lld,%lld,%.2f,%.1f,%.1f,%.1f\n", r.t_s,
               r.process.rss_kib, r.process.fds, r.process.threads, s.mode, static_cast<long long>(s.goals_received),
               static_cast<long long>(s.plans_succeeded), static_cast<long long>(s.plans_failed),
               static_cast<long long>(s.frames_sent), static_cast<long long>(s.can_errors),
               static_cast<long long>(s.decode_errors), static_cast<long long>(s.stream_overruns),
               static_cast<long long>(s.publish_failures), s.plan_time_p99_ms, s.stream_jitter_p99_us,
               s.stream_jitter_max_us, s.state_age_ms);
  std::fflush(csv);
}

}  // namespace

int main(int argc, char** argv) {
  const auto parsed = parse(argc, argv);
  if (!parsed) {
    std::fprintf(stderr,
                 "usage: cyber-soak-peer --daemon-pid PID --seconds S [--warmup S] [--sample-s S] [--csv FILE] "
                 "[--seed N] [--lcm-url URL] [--rss-slack-kib K]\n");
    return 2;
  }
  const Args& args = *parsed;
  const double warmup_s = args.warmup_s.value_or(std::min(60.0, args.seconds / 4));
  std::signal(SIGTERM, [](int) { g_stop = 1; });
  std::signal(SIGINT, [](int) { g_stop = 1; });

  lcm::LCM lcm(args.lcm_url);
  if (!lcm.good()) {
    std::fprintf(stderr, "cyber-soak-peer: cannot open LCM\n");
    return 1;
  }
  Peer peer;
  lcm.subscribe("ARM_SETPOINT", &Peer::onSetpoint, &peer);
  lcm.subscribe("ARM_DAEMON_STATUS", &Peer::onDaemonStatus, &peer);
  // Unbounded queue: a burst's answers arrive faster than one period (see test_peer.cpp, watch).
  lcm.subscribe("ARM_PLAN_STATUS", &Peer::onPlanStatus, &peer)->setQueueCapacity(0);

  std::FILE* csv = args.csv_path.empty() ? nullptr : std::fopen(args.csv_path.c_str(), "w");
  if (csv) writeCsvHeader(csv);

  // The daemon counts as started once it holds (it opens LCM only after building the planner's
  // grids): goals sent earlier would go unheard, not unanswered.
  const auto ready_by = Clock::now() + std::chrono::seconds(120);
  while (!g_stop && !(peer.status && peer.status->mode == cyberplanner::arm_daemon_status_t::MODE_HOLDING)) {
    if (Clock::now() > ready_by || !sampleProcess(args.daemon_pid)) {
      std::fprintf(stderr, "cyber-soak-peer: the daemon did not start holding within 120 s\n");
      return 1;
    }
    publishState(lcm, peer);
    lcm.handleTimeout(10);
  }

  std::mt19937 random(args.seed);
  GoalSender sender(lcm, peer, random);
  std::vector<Row> rows;
  std::vector<std::string> failures;
  long long state_publish_failures = 0, lost = 0, status_gaps = 0;
  const auto start = Clock::now();
  const auto period = std::chrono::microseconds(10'000);  // 100 Hz
  auto next_tick = start;
  double next_goal_s = 1.0, next_sample_s = 0.0;
  bool sending_goals = true;
  double drain_until_s = args.seconds + args.answer_timeout_s;

  while (!g_stop) {
    const double t = secondsSince(start);
    if (sending_goals && t >= args.seconds) sending_goals = false;
    if (!sending_goals && (peer.open_goals.empty() || t >= drain_until_s)) break;

    if (!publishState(lcm, peer)) ++state_publish_failures;

    if (sending_goals && t >= next_goal_s) next_goal_s = t + sender.send(pickKind(random));

    if (t >= next_sample_s) {
      next_sample_s += args.sample_s;
      const auto process = sampleProcess(args.daemon_pid);
      if (!process) {
        failures.push_back("the daemon (pid " + std::to_string(args.daemon_pid) +
                           ") is gone at t=" + std::to_string(static_cast<int>(t)) + " s");
        break;
      }
      if (peer.status && std::chrono::duration<double>(Clock::now() - peer.status_at).count() > 2.0) ++status_gaps;
      Row row{t, *process, peer.status.value_or(cyberplanner::arm_daemon_status_t{})};
      rows.push_back(row);
      if (csv) writeCsvRow(csv, row);
    }

    // A goal without an answer for answer_timeout_s is lost.
    for (auto it = peer.open_goals.begin(); it != peer.open_goals.end();) {
      if (std::chrono::duration<double>(Clock::now() - it->second).count() > args.answer_timeout_s) {
        ++lost;
        if (lost <= 10)
          std::fprintf(stderr, "cyber-soak-peer: no final status for request %lld\n",
                       static_cast<long long>(it->first));
        it = peer.open_goals.erase(it);
      } else {
        ++it;
      }
    }

    next_tick += period;
    while (lcm.handleTimeout(0) > 0) {
    }
    std::this_thread::sleep_until(next_tick);
    if (Clock::now() > next_tick + 10 * period) next_tick = Clock::now();  // descheduled: no catch-up burst
  }
  if (csv) std::fclose(csv);
  if (g_stop) failures.push_back("interrupted");

  // ---- checks ----
  long long duplicates = 0, answered = 0;
  for (const auto& [id, n] : peer.finals) {
    duplicates += n > 1 ? 1 : 0;
    answered += n > 0 ? 1 : 0;
  }
  lost += static_cast<long long>(peer.open_goals.size());
  if (lost > 0) failures.push_back(std::to_string(lost) + " goals without a final status");
  if (duplicates > 0) failures.push_back(std::to_string(duplicates) + " goals with more than one final status");
  if (status_gaps > 0) failures.push_back(std::to_string(status_gaps) + " samples saw no ARM_DAEMON_STATUS for 2 s");
  if (!peer.status) failures.push_back("no ARM_DAEMON_STATUS at all");
  if (peer.status && peer.status->publish_failures > 0) {
    failures.push_back(std::to_string(peer.status->publish_failures) + " LCM publish failures in the daemon");
  }

  std::vector<long> early_rss, late_rss;
  long warm_fds = -1, warm_threads = -1, max_fds = -1, max_threads = -1, max_rss = -1;
  std::vector<const Row*> after;
  for (const auto& row : rows) {
    if (row.t_s >= warmup_s && row.t_s <= args.seconds) after.push_back(&row);
  }
  if (after.size() >= 10) {
    const size_t tenth = after.size() / 10;
    for (size_t i = 0; i < tenth; ++i) early_rss.push_back(after[i]->process.rss_kib);
    for (size_t i = after.size() - tenth; i < after.size(); ++i) late_rss.push_back(after[i]->process.rss_kib);
    warm_fds = after.front()->process.fds;
    warm_threads = after.front()->process.threads;
    for (const Row* row : after) {
      max_fds = std::max(max_fds, row->process.fds);
      max_threads = std::max(max_threads, row->process.threads);
      max_rss = std::max(max_rss, row->process.rss_kib);
    }
    if (median(late_rss) > median(early_rss) + args.rss_slack_kib) {
      failures.push_back("RSS grew from " + std::to_string(median(early_rss)) + " KiB to " +
                         std::to_string(median(late_rss)) + " KiB after the warm-up");
    }
    if (max_fds > warm_fds)
      failures.push_back("open fds rose from " + std::to_string(warm_fds) + " to " + std::to_string(max_fds));
    if (max_threads > warm_threads) {
      failures.push_back("threads rose from " + std::to_string(warm_threads) + " to " + std::to_string(max_threads));
    }
  } else {
    failures.push_back("too few samples after the warm-up (" + std::to_string(after.size()) + ")");
  }

  const auto s = peer.status.value_or(cyberplanner::arm_daemon_status_t{});
  std::printf("soak_seconds=%.0f\nwarmup_seconds=%.0f\nsamples=%zu\n", args.seconds, warmup_s, rows.size());
  std::printf("goals_sent=%lld\nmalformed_sent=%lld\nbursts=%lld\nanswered=%lld\nlost=%lld\nduplicates=%lld\n",
              sender.sent, sender.malformed_sent, sender.bursts, answered, lost, duplicates);
  std::printf("done=%lld\nrejected=%lld\nfailed=%lld\ncancelled=%lld\n", peer.by_status[3], peer.by_status[4],
              peer.by_status[5], peer.by_status[6]);
  std::printf(
      "rss_kib_early_median=%ld\nrss_kib_late_median=%ld\nrss_kib_max=%ld\nfds_warm=%ld\nfds_max=%ld\n"
      "threads_warm=%ld\nthreads_max=%ld\n",
      median(early_rss), median(late_rss), max_rss, warm_fds, max_fds, warm_threads, max_threads);
  std::printf(
      "daemon_goals_received=%lld\ndaemon_plans_succeeded=%lld\ndaemon_plans_failed=%lld\n"
      "daemon_frames_sent=%lld\ndaemon_can_errors=%lld\ndaemon_decode_errors=%lld\n"
      "daemon_stream_overruns=%lld\ndaemon_publish_failures=%lld\n"
      "daemon_plan_time_p50_ms=%.2f\ndaemon_plan_time_p99_ms=%.2f\ndaemon_plan_time_max_ms=%.2f\n"
      "daemon_stream_jitter_p50_us=%.1f\ndaemon_stream_jitter_p99_us=%.1f\ndaemon_stream_jitter_max_us=%.1f\n",
      static_cast<long long>(s.goals_received), static_cast<long long>(s.plans_succeeded),
      static_cast<long long>(s.plans_failed), static_cast<long long>(s.frames_sent),
      static_cast<long long>(s.can_errors), static_cast<long long>(s.decode_errors),
      static_cast<long long>(s.stream_overruns), static_cast<long long>(s.publish_failures), s.plan_time_p50_ms,
      s.plan_time_p99_ms, s.plan_time_max_ms, s.stream_jitter_p50_us, s.stream_jitter_p99_us, s.stream_jitter_max_us);
  std::printf("peer_publish_failures=%lld\nstatus_messages=%lld\nforeign_finals=%lld\n",
              sender.publish_failures + state_publish_failures, peer.status_messages, peer.foreign_finals);
  for (const auto& failure : failures) std::printf("FAIL: %s\n", failure.c_str());
  return failures.empty() ? 0 : 1;
}
