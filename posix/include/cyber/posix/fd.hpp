#pragma once
// Owned file descriptors for event loops: eventfd, timerfd, signalfd and epoll, closed on
// destruction. Creation failures throw std::system_error (start-up only); times are absolute
// CLOCK_MONOTONIC nanoseconds.

#include <csignal>
#include <cstdint>
#include <initializer_list>

namespace cyber::posix {

class UniqueFd {
 public:
  UniqueFd() = default;
  explicit UniqueFd(int fd) : fd_(fd) {}
  UniqueFd(UniqueFd&& other) noexcept : fd_(other.release()) {}
  UniqueFd& operator=(UniqueFd&& other) noexcept;
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;
  ~UniqueFd();

  [[nodiscard]] int get() const { return fd_; }
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_ = -1;
};

// A counter another thread bumps to wake the loop. signal() never blocks and is async-safe.
class EventFd {
 public:
  EventFd();
  void signal() const;
  void drain() const;
  [[nodiscard]] int fd() const { return fd_.get(); }

 private:
  UniqueFd fd_;
};

// CLOCK_MONOTONIC timer. wait() blocks until it fires and returns the expirations since the last
// read; consume() reads without blocking (0 when it has not fired).
class TimerFd {
 public:
  explicit TimerFd(bool blocking = false);
  // Periodic, first expiry at first_ns (absolute).
  void startPeriodic(std::int64_t first_ns, std::int64_t period_ns) const;
  void startOnce(std::int64_t at_ns) const;
  void stop() const;
  std::uint64_t wait() const;
  std::uint64_t consume() const;
  [[nodiscard]] int fd() const { return fd_.get(); }

 private:
  UniqueFd fd_;
};

// Blocks the signals in the calling thread (and threads it creates later) and reads them from an
// fd. Create it in main before any other thread starts.
class SignalFd {
 public:
  explicit SignalFd(std::initializer_list<int> signals);
  // The next pending signal number, or 0.
  int take() const;
  [[nodiscard]] int fd() const { return fd_.get(); }

 private:
  UniqueFd fd_;
};

// An epoll set of readable descriptors, each reported by the tag it was added with.
class Epoll {
 public:
  Epoll();
  void add(int fd, std::uint64_t tag) const;
  // Blocks until at least one is readable; fills at most capacity tags and returns their count
  // (0 when a signal interrupted the wait, -1 with errno on failure).
  int wait(std::uint64_t* tags, int capacity) const;
  [[nodiscard]] int fd() const { return fd_.get(); }

 private:
  UniqueFd fd_;
};

}  // namespace cyber::posix
