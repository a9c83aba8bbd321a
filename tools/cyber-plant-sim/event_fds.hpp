#pragma once
// The file descriptors of the simulator's event loop: epoll, monotonic timerfds and a signalfd
// for SIGINT/SIGTERM. RAII, no exceptions: creation failures come back as an errno.

#include <cstdint>
#include <string>

namespace cyber::plant {

// Seconds on CLOCK_MONOTONIC and microseconds on CLOCK_REALTIME.
double monotonicSeconds();
std::int64_t realtimeMicros();

class OwnedFd {
 public:
  OwnedFd() = default;
  explicit OwnedFd(int fd) : fd_(fd) {}
  OwnedFd(OwnedFd&& other) noexcept : fd_(other.release()) {}
  OwnedFd& operator=(OwnedFd&& other) noexcept;
  OwnedFd(const OwnedFd&) = delete;
  OwnedFd& operator=(const OwnedFd&) = delete;
  ~OwnedFd();

  [[nodiscard]] int get() const { return fd_; }
  [[nodiscard]] bool valid() const { return fd_ >= 0; }
  int release();

 private:
  int fd_ = -1;
};

// A CLOCK_MONOTONIC timerfd, non-blocking.
class MonotonicTimer {
 public:
  static MonotonicTimer create(std::string& error);
  [[nodiscard]] int fd() const { return fd_.get(); }
  [[nodiscard]] bool valid() const { return fd_.valid(); }
  // First expiry at absolute monotonic time first_s, then every period_s (0: once).
  bool arm(double first_s, double period_s);
  bool disarm();
  // Expirations since the last read (0 when none).
  std::uint64_t consume();

 private:
  OwnedFd fd_;
};

// SIGINT and SIGTERM blocked and delivered through a non-blocking signalfd.
OwnedFd makeStopSignalFd(std::string& error);

// An epoll set; add() registers fd for EPOLLIN with `tag` as its data.
class EventPoll {
 public:
  static EventPoll create(std::string& error);
  [[nodiscard]] bool valid() const { return fd_.valid(); }
  bool add(int fd, std::uint64_t tag);
  // Waits for events; fills tags (at most capacity); returns the count or -1 (errno) on failure.
  int wait(std::uint64_t* tags, int capacity);

 private:
  OwnedFd fd_;
};

}  // namespace cyber::plant
