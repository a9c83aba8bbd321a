#include "cyber/daemon/io/state_receiver.hpp"

#include <poll.h>

#include <array>
#include <cerrno>

#include "cyber/daemon/io/thread_priority.hpp"

namespace cyber::daemon::io {

StateReceiver::StateReceiver(lcm::LCM& lcm, std::string channel, LcmInput& input)
    : lcm_(lcm), channel_(std::move(channel)), input_(input) {}

StateReceiver::~StateReceiver() { stop(); }

int StateReceiver::start() {
  thread_ = std::thread([this] { run(); });
  pollfd ready{subscribed_.fd(), POLLIN, 0};
  while (::poll(&ready, 1, -1) < 0 && errno == EINTR) {
  }
  return priority_.load();
}

void StateReceiver::stop() {
  quitting_.store(true);
  quit_.signal();
  if (thread_.joinable()) thread_.join();
}

void StateReceiver::run() {
  priority_.store(requestRealtimePriority(kStateReceiverPriority));
  lcm_.subscribe(channel_, &StateReceiver::onMessage, this);  // starts LCM's receive thread
  std::array<pollfd, 2> fds{pollfd{lcm_.getFileno(), POLLIN, 0}, pollfd{quit_.fd(), POLLIN, 0}};
  subscribed_.signal();
  while (!quitting_.load()) {
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      return;
    }
    // LCM's descriptor failing (its receive thread gone) would make every poll return at once:
    // spinning here at real-time priority would starve the whole machine, so the thread ends
    // and ARM_STATE goes stale, which stops motion and says so.
    if (fds[0].revents & (POLLERR | POLLHUP | POLLNVAL)) return;
    if (fds[0].revents & POLLIN) lcm_.handleTimeout(0);
  }
}

void StateReceiver::onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  deliverDecoded<cyberplanner::arm_state_t>(
      buffer, channel, [this](const cyberplanner::arm_state_t& message) { input_.onState(message); },
      [this](const std::string& name, int size) { input_.onUndecodableState(name, size); });
}

}  // namespace cyber::daemon::io
