#pragma once
// ARM_STATE on an LCM instance and a thread of its own, at SCHED_FIFO kStateReceiverPriority when
// allowed (thread_priority.hpp). A state is stamped when it is handed over (LcmInput::onState), so
// any delay between its arrival and its handling counts as its age: on the event loop, a busy
// machine or the daemon's own work (a goal flood, logging) made a fresh state look stale
// (docs/design.md, "Threads and ownership"). LCM's own receive thread is created by the first
// subscription and inherits the scheduling of the thread that subscribes, so this thread raises
// itself first and then subscribes.

#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <string>
#include <thread>

#include "cyber/daemon/io/fd.hpp"
#include "cyber/daemon/io/lcm_input.hpp"

namespace cyber::daemon::io {

class StateReceiver {
 public:
  // `lcm` (used by this thread alone once started) and `input` must outlive this.
  StateReceiver(lcm::LCM& lcm, std::string channel, LcmInput& input);
  StateReceiver(const StateReceiver&) = delete;
  StateReceiver& operator=(const StateReceiver&) = delete;
  ~StateReceiver();

  // Starts the thread and returns once it has subscribed: the SCHED_FIFO priority it was granted,
  // 0 when refused (it then runs at the scheduling it inherited).
  int start();
  void stop();

 private:
  void run();
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel);

  lcm::LCM& lcm_;
  std::string channel_;
  LcmInput& input_;
  EventFd quit_;
  EventFd subscribed_;
  std::atomic<bool> quitting_{false};
  std::atomic<int> priority_{0};
  std::thread thread_;
};

}  // namespace cyber::daemon::io
