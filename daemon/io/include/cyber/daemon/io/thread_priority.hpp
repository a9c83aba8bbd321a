#pragma once
// The scheduling of the daemon's threads (docs/design.md, "Threads and ownership"). A thread
// inherits its creator's policy, so each thread sets its own: the streamer and the ARM_STATE
// receiver ask for SCHED_FIFO, the planning worker and the logger set SCHED_OTHER explicitly.

namespace cyber::daemon::io {

// The streamer must never wait for anything else of the daemon.
inline constexpr int kStreamerPriority = 50;
// Below the streamer, which must not wait for a state; above every SCHED_OTHER thread, so that
// neither the daemon's own work (a goal flood, planning, logging) nor the machine's load can delay
// the stamping of a fresh ARM_STATE past state_timeout_s. Also above the peers the tests run at
// real-time priority (the plant simulator at 40, the test peers at 20): a state is stamped as soon
// as its sender's datagram arrives, not when that sender next sleeps.
inline constexpr int kStateReceiverPriority = 45;

// Asks for SCHED_FIFO `priority` for the calling thread: the priority granted, 0 when refused
// (unprivileged without RLIMIT_RTPRIO, docs/operations.md) and the thread keeps its policy.
int requestRealtimePriority(int priority);

// SCHED_OTHER for the calling thread, whatever its creator had.
void useNormalScheduling();

}  // namespace cyber::daemon::io
